#include "class_sections.h"

#include "class_finish.h"
#include "error.h"

#include <map>
#include <set>

namespace raylab {

namespace fs = std::filesystem;

std::string sectionFolderName(const std::string& section) {
    std::string out;
    for (char c : section) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
        out += keep ? c : '_';
    }
    if (out.empty() || out == "." || out == "..") out = "_" + out;
    return out;
}

namespace {

// FROM's files under TO, each a hard link where it can be, else a copy.
void linkTree(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    if (!fs::is_directory(from, ec)) return;
    fs::create_directories(to);
    for (fs::recursive_directory_iterator it(from), end; it != end; ++it) {
        const fs::path target = to / fs::relative(it->path(), from);
        if (it->is_directory()) {
            fs::create_directories(target);
        } else if (it->is_regular_file()) {
            fs::create_hard_link(it->path(), target, ec);
            if (ec) fs::copy_file(it->path(), target, fs::copy_options::overwrite_existing);
        }
    }
}

}  // namespace

std::vector<std::pair<std::string, std::string>> writeSectionReports(const ClassResult& result,
                                                                     const fs::path& outDir) {
    std::error_code ec;
    fs::remove_all(outDir / "sections", ec);  // never a section of an earlier run
    std::map<std::string, std::vector<const StudentResult*>> bySection;
    for (const StudentResult& st : result.students)
        if (!st.roster.section.empty()) bySection[st.roster.section].push_back(&st);
    std::vector<std::pair<std::string, std::string>> links;
    std::set<std::string> folders;
    for (const auto& [section, students] : bySection) {
        std::string folder = sectionFolderName(section);
        for (int n = 2; !folders.insert(folder).second; ++n)
            folder = sectionFolderName(section) + "-" + std::to_string(n);
        const fs::path dir = outDir / "sections" / folder;
        ClassResult part = result;
        part.students.clear();
        for (const StudentResult* st : students) part.students.push_back(*st);
        matchMistakes(part);  // the section's own likenesses
        try {
            for (const std::string& stage : result.stages)
                linkTree(outDir / "reference" / stage, dir / "reference" / stage);
            for (const StudentResult& st : part.students)
                if (st.hasFolder)
                    linkTree(outDir / "students" / st.name, dir / "students" / st.name);
        } catch (const fs::filesystem_error& e) {
            throw Error("section " + section + ": cannot link the class's files into " +
                        dir.string() + " (" + e.code().message() + ")");
        }
        writeSummaryCsv(part, dir / "summary.csv");
        ClassPageOptions options;
        options.title = "RayLab grading report: section " + section;
        writeHtmlReport(part, dir, options);
        links.emplace_back(section, "sections/" + folder + "/report.html");
    }
    return links;
}

}  // namespace raylab
