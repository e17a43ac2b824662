#include "test_support.h"

#include <algorithm>

#include "gl_context.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <sys/wait.h>

namespace raylab::test {

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void writeFile(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
}

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

CommandResult runCommand(const std::string& command) {
    ScratchDir tmp;
    const fs::path out = tmp / "stdout", err = tmp / "stderr";
    std::string full = "(" + command + ") </dev/null >" + quote(out) + " 2>" + quote(err);
    int status = std::system(full.c_str());
    CommandResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = readFile(out);
    r.err = readFile(err);
    return r;
}

CommandResult runRaylab(const std::string& args) {
    return runCommand(quote(RAYLAB_EXE) + " " + args);
}
CommandResult runLabgen(const std::string& args) {
    return runCommand(quote(RAYLAB_LABGEN_EXE) + " " + args);
}

fs::path sourceDir() { return RAYLAB_SOURCE_DIR; }
fs::path raylabExe() { return RAYLAB_EXE; }

ScratchDir::ScratchDir() {
    std::random_device rd;
    path_ =
        fs::temp_directory_path() / ("raylab-test-" + std::to_string(rd()) + std::to_string(rd()));
    fs::create_directories(path_);
}

ScratchDir::~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::vector<std::string> filesUnder(const fs::path& dir) {
    std::vector<std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files.push_back(fs::relative(e.path(), dir).string());
    std::sort(files.begin(), files.end());
    return files;
}

void writeSolvedLabs(const fs::path& dir) {
    CommandResult r = runLabgen("--solved " + quote(dir));
    ASSERT_EQ(r.exitCode, 0) << r.all();
}

void replaceInFile(const fs::path& file, const std::string& from, const std::string& to) {
    std::string text = readFile(file);
    auto at = text.find(from);
    ASSERT_NE(at, std::string::npos)
        << "'" << from << "' not found in " << file << " - did the solution change?";
    text.replace(at, from.size(), to);
    writeFile(file, text);
}

std::vector<std::string> failedViews(const std::string& checkOutput) {
    std::vector<std::string> views;
    std::istringstream in(checkOutput);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string verdict, name;
        words >> verdict >> name;
        if (verdict == "FAIL") views.push_back(name);
    }
    return views;
}

void ensureGlContext() {
    static std::unique_ptr<GlContext> context = createHeadlessContext(Backend::Auto);
}

ShaderSource assembledFrom(const std::string& file, const std::string& text) {
    ShaderSource s;
    s.text = std::string(kGlslVersionLine) + "\n" + text;
    s.origin.push_back({"<raylab>", 1});
    std::istringstream in(text);
    int n = 1;
    for (std::string line; std::getline(in, line);) s.origin.push_back({file, n++});
    return s;
}

std::string studentPages(const fs::path& out) {
    std::string pages;
    std::error_code ec;
    for (fs::directory_iterator it(out / "students", ec), end; !ec && it != end; it.increment(ec))
        if (fs::is_regular_file(it->path() / "report.html"))
            pages += readFile(it->path() / "report.html");
    return pages;
}

}  // namespace raylab::test
