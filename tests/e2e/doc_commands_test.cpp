// The instructors' documented command lines, run as written: every ```sh
// block of README.md's "For instructors", docs/grading.md and
// examples/*/README.md, line by line, in a fresh folder laid out like the
// RayLab folder (its parts linked in, build/ the build being tested), so the
// docs cannot drift from what works.
//
// What a block is for is said in an HTML comment on the line before it
// (invisible in the rendered page):
//   <!-- doc-test: run -->             run here (label e2e)
//   <!-- doc-test: run cluster -->     run by the cluster test (label cluster:
//                                      root, Debian's slurm-wlm and munge);
//                                      "..., inside examples/slurm/local_cluster.sh"
//                                      runs it in a one-node cluster of its own
//   <!-- doc-test: file NAME -->       not a command: the block is written to
//                                      NAME first (a sample roster, a course file)
//   <!-- doc-test: skip WHY -->        not run, and why
// A ```sh block with none of these fails the test: no documented command
// goes untested by accident. Before the commands a folder class/ of three
// students is made (alice solved 01-02, bob a catalogued mistake in 02,
// carol 01 only): the docs' "your class".
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <regex>
#include <sstream>

using namespace raylab::test;

namespace {

struct Block {
    std::string doc;     // "examples/slurm/README.md"
    int line = 0;        // of the opening fence
    std::string lang;    // "sh", "json", "csv"
    std::string marker;  // the doc-test comment's text after "doc-test:", trimmed
    std::string text;
};

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// The fenced blocks of DOC between the lines starting with FROM and UNTIL
// (empty: the whole file).
std::vector<Block> blocks(const std::string& doc, const std::string& from = "",
                          const std::string& until = "") {
    std::istringstream in(readFile(sourceDir() / doc));
    std::vector<Block> out;
    std::string line, marker;
    bool inside = from.empty(), fenced = false;
    int n = 0;
    Block b;
    const std::regex comment(R"(^<!-- doc-test:(.*)-->\s*$)");
    while (std::getline(in, line)) {
        ++n;
        if (!from.empty() && line.rfind(from, 0) == 0) inside = true;
        else if (!until.empty() && inside && line.rfind(until, 0) == 0) break;
        if (!inside) continue;
        if (fenced) {
            if (line.rfind("```", 0) == 0) {
                fenced = false;
                out.push_back(b);
            } else {
                b.text += line + "\n";
            }
            continue;
        }
        std::smatch m;
        if (std::regex_match(line, m, comment)) {
            marker = trim(m[1]);
        } else if (line.rfind("```", 0) == 0) {
            fenced = true;
            b = Block{doc, n, trim(line.substr(3)), marker, ""};
            marker.clear();
        } else if (!trim(line).empty()) {
            marker.clear();  // a marker belongs to the block right after it
        }
    }
    return out;
}

std::vector<Block> instructorBlocks() {
    std::vector<Block> all = blocks("README.md", "## For instructors", "## Tests");
    for (const char* doc : {"docs/grading.md", "examples/gradescope/README.md",
                            "examples/prairielearn/README.md", "examples/slurm/README.md"}) {
        std::vector<Block> b = blocks(doc);
        all.insert(all.end(), b.begin(), b.end());
    }
    return all;
}

// The command lines of a block: comments and blank lines dropped, lines
// ending in a backslash joined.
std::vector<std::string> commands(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string pending;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\\') {
            pending += line.substr(0, line.size() - 1) + " ";
            continue;
        }
        line = pending + line;
        pending.clear();
        if (trim(line).empty() || trim(line)[0] == '#') continue;
        out.push_back(line);
    }
    return out;
}

// A folder laid out like the RayLab folder: its parts linked in, build/ this build.
void layOutRaylabFolder(const fs::path& at) {
    for (const auto& e : fs::directory_iterator(sourceDir())) {
        const std::string name = e.path().filename().string();
        if (name == "build" || name == ".git" || name[0] == '.') continue;
        fs::create_symlink(e.path(), at / name);
    }
    fs::create_directory_symlink(raylabExe().parent_path(), at / "build");
}

// class/: alice solved 01-02, bob a catalogued mistake in 02, carol 01 only.
void writeClass(const fs::path& cls) {
    ScratchDir solved;
    writeSolvedLabs(solved.path());
    for (const char* student : {"alice", "bob", "carol"})
        for (const char* stage : {"01-raycast", "02-shading"}) {
            if (std::string(student) == "carol" && std::string(stage) == "02-shading") continue;
            fs::create_directories(cls / student);
            fs::copy(solved / stage, cls / student / stage, fs::copy_options::recursive);
        }
    const auto mistake = nlohmann::json::parse(
        readFile(sourceDir() / "tests/mistakes/02-shading/phong-instead-of-blinn.json"));
    for (const auto& pair : mistake["replace"])
        replaceInFile(cls / "bob" / "02-shading" / mistake["file"].get<std::string>(), pair[0],
                      pair[1]);
}

// Runs every block of DOCS whose marker starts with "run" and is KIND ("" or
// "cluster"), each doc in a folder of its own; files first where they stand.
void runDocs(const std::string& kind) {
    std::map<std::string, std::vector<Block>> byDoc;
    for (const Block& b : instructorBlocks()) byDoc[b.doc].push_back(b);
    int ran = 0;
    for (const auto& [doc, list] : byDoc) {
        ScratchDir dir;
        layOutRaylabFolder(dir.path());
        writeClass(dir / "class");
        for (const Block& b : list) {
            SCOPED_TRACE(doc + ":" + std::to_string(b.line));
            if (b.marker.rfind("file ", 0) == 0) {
                writeFile(dir / trim(b.marker.substr(5)), b.text);
                continue;
            }
            const bool cluster = b.marker.rfind("run cluster", 0) == 0;
            if (b.marker.rfind("run", 0) != 0 || cluster != (kind == "cluster")) continue;
            const bool inCluster =
                b.marker.find("inside examples/slurm/local_cluster.sh") != std::string::npos;
            for (const std::string& command : commands(b.text)) {
                const std::string line = inCluster ? "examples/slurm/local_cluster.sh slurm-" +
                                                         std::to_string(ran) + "/ bash -c " +
                                                         quote(command)
                                                   : command;
                const auto start = std::chrono::steady_clock::now();
                // On lines of their own: a trailing "# comment" must not eat
                // what runCommand adds after the command.
                CommandResult r = runCommand("cd " + quote(dir.path()) + " && {\n" + line + "\n}");
                const double s =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                std::printf("[ doc      ] %s:%d (%.1f s): %s\n", doc.c_str(), b.line, s,
                            command.c_str());
                EXPECT_EQ(r.exitCode, 0) << doc << ":" << b.line << ": " << command << "\n"
                                         << r.all();
                ++ran;
            }
        }
        // The Gradescope README's local try: alice's two solved stages earn
        // all of their points, as on Gradescope.
        if (doc == "examples/gradescope/README.md" && kind.empty()) {
            const fs::path results = dir / "try-gradescope/results/results.json";
            ASSERT_TRUE(fs::exists(results)) << "the README's local run wrote no results.json";
            const auto j = nlohmann::json::parse(readFile(results));
            EXPECT_DOUBLE_EQ(j["score"].get<double>(), 200.0) << j.dump(1);
        }
    }
    EXPECT_GT(ran, 0);
}

}  // namespace

// Every ```sh block says what it is for, and the markers are well formed.
TEST(DocCommands, EveryShellBlockIsRunOrSaysWhyNot) {
    int shell = 0;
    for (const Block& b : instructorBlocks()) {
        SCOPED_TRACE(b.doc + ":" + std::to_string(b.line));
        const bool known = b.marker == "run" || b.marker.rfind("run cluster", 0) == 0 ||
                           b.marker.rfind("file ", 0) == 0 ||
                           (b.marker.rfind("skip ", 0) == 0 && b.marker.size() > 10);
        if (b.lang == "sh") {
            ++shell;
            EXPECT_TRUE(known && b.marker.rfind("file ", 0) != 0)
                << "a shell block no test runs (mark it <!-- doc-test: run --> or say why not): "
                << b.text;
        } else if (!b.marker.empty()) {
            EXPECT_EQ(b.marker.rfind("file ", 0), 0u) << "only a file can be a " << b.lang;
        }
    }
    EXPECT_GE(shell, 8);
    // The parser finds what it looks for: a block after a marker, none after text.
    writeFile(fs::path(testing::TempDir()) / "doc.md",
              "x\n<!-- doc-test: run -->\n```sh\na \\\n b\n# c\n```\ntext\n```sh\nd\n```\n");
    const fs::path rel = fs::relative(fs::path(testing::TempDir()) / "doc.md", sourceDir());
    const std::vector<Block> b = blocks(rel.string());
    ASSERT_EQ(b.size(), 2u);
    EXPECT_EQ(b[0].marker, "run");
    EXPECT_EQ(commands(b[0].text), std::vector<std::string>{"a   b"});
    EXPECT_EQ(b[1].marker, "");
}

TEST(DocCommands, InstructorCommandsRunAsWritten) { runDocs(""); }

// Label cluster (tests/CMakeLists.txt): needs root and Debian's slurm-wlm and munge.
TEST(DocCommands, SlurmCommandsRunAsWritten) {
    if (!std::getenv("RAYLAB_DOC_TEST_CLUSTER"))
        GTEST_SKIP() << "run by ctest -L cluster (RAYLAB_DOC_TEST_CLUSTER=1)";
    runDocs("cluster");
}

// The docs' count of catalogued mistakes is the catalogue's.
TEST(DocCommands, TheCountOfCataloguedMistakesIsTheCatalogues) {
    std::size_t n = 0;
    for (const auto& stage : fs::directory_iterator(sourceDir() / "tests/mistakes"))
        if (stage.is_directory())
            for (const auto& e : fs::directory_iterator(stage.path()))
                n += e.path().extension() == ".json";
    const std::string count = std::to_string(n);
    EXPECT_NE(readFile(sourceDir() / "README.md").find("replacements (" + count + " across"),
              std::string::npos)
        << "README.md: the catalogue holds " << count;
    EXPECT_NE(readFile(sourceDir() / "docs/grading.md")
                  .find("typical mistakes of each stage (" + count + ")"),
              std::string::npos)
        << "docs/grading.md: the catalogue holds " << count;
}
