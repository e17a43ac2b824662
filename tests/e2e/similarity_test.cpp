// `raylab similarity`: a class of independent solutions of the open labs 01,
// 04 and f3 (the course's own; dana's, eli's and bea's, written from the
// open guides alone by helpers who never saw the solution; kim's and lou's,
// of 01 and 04, in other styles by a developer who had:
// tests/similarity/independent/) and
// copies planted from them as copiers
// disguise them: variables renamed, functions reordered, comments and layout
// changed, and all three at once. Every planted pair must be flagged, no
// pair of independent solutions, and the code everyone was handed never
// counts.
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

using namespace raylab::test;

namespace {

const char* const kStages[] = {"01-raycast", "04-recursion", "f3-fins"};

// Every name declared after a type (a local, a parameter, a struct member)
// renamed, as a copier does with search and replace.
std::string renamed(std::string text) {
    static const std::regex declaration(
        R"(\b(?:float|int|bool|vec2|vec3|vec4|Hit|Ray|Surface|Material|Job)\s+([a-z_]\w*)\b(?!\s*\())");
    std::set<std::string> names;
    for (std::sregex_iterator it(text.begin(), text.end(), declaration), end; it != end; ++it)
        names.insert((*it)[1]);
    int k = 0;
    for (const std::string& n : names)
        text = std::regex_replace(text, std::regex("\\b" + n + "\\b"),
                                  "my" + std::to_string(k++) + std::string(n.rbegin(), n.rend()));
    return text;
}

// The file's top-level pieces (each ending in a line "}" or "};") in the
// opposite order.
std::string reordered(const std::string& text) {
    std::vector<std::string> pieces;
    std::string piece, line;
    std::istringstream in(text);
    while (std::getline(in, line)) {
        piece += line + "\n";
        if (line == "}" || line == "};") {
            pieces.push_back(piece);
            piece.clear();
        }
    }
    std::string out;
    for (auto it = pieces.rbegin(); it != pieces.rend(); ++it) out += *it + "\n";
    return out + piece;
}

// Comments gone, other ones added, every line indented anew, blank lines dropped.
std::string recommented(const std::string& text) {
    const std::string bare = std::regex_replace(text, std::regex("//[^\n]*"), "");
    std::string out = "// my own work, written from scratch\n", line;
    std::istringstream in(bare);
    for (int n = 0; std::getline(in, line);) {
        const std::size_t a = line.find_first_not_of(" \t");
        if (a == std::string::npos) continue;
        out += "  " + line.substr(a) + (++n % 7 == 3 ? "    // careful here" : "") + "\n";
    }
    return out;
}

void plant(const fs::path& from, const fs::path& to,
           const std::vector<std::string (*)(const std::string&)>& disguises) {
    for (const char* stage : kStages) {
        if (!fs::is_directory(from / stage)) continue;
        fs::create_directories(to / stage);
        for (const auto& e : fs::directory_iterator(from / stage)) {
            if (e.path().extension() != ".glsl" && e.path().extension() != ".geom") continue;
            std::string text = readFile(e.path());
            for (auto disguise : disguises) text = disguise(text);
            writeFile(to / stage / e.path().filename(), text);
        }
    }
}

std::string renamedText(const std::string& t) { return renamed(t); }

// pairs.csv: "a,b" -> flagged, for the stage; SCORES (optional) gets each
// pair's larger score.
std::map<std::string, bool> flaggedPairs(const fs::path& csv, const std::string& stage,
                                         std::map<std::string, double>* scores = nullptr) {
    std::map<std::string, bool> pairs;
    std::istringstream in(readFile(csv));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "stage,student_a,student_b,similarity_a,similarity_b,flagged");
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream cells(line);
        for (std::string c; std::getline(cells, c, ',');) f.push_back(c);
        if (f.size() != 6 || f[0] != stage) continue;
        pairs[f[1] + "," + f[2]] = f[5] == "1";
        if (scores) (*scores)[f[1] + "," + f[2]] = std::max(std::stod(f[3]), std::stod(f[4]));
    }
    return pairs;
}

}  // namespace

TEST(Similarity, PlantedCopiesAreFlaggedAndIndependentSolutionsAreNot) {
    ScratchDir dir;
    const fs::path cls = dir / "class";
    // The independent solutions: the course's own (solved labs) and two others.
    writeSolvedLabs(dir / "solved");
    for (const char* stage : kStages) {
        fs::create_directories(cls / "ada" / stage);
        fs::copy(dir / "solved" / stage, cls / "ada" / stage, fs::copy_options::recursive);
    }
    for (const char* who : {"kim", "lou", "dana", "eli", "bea"}) {
        fs::create_directories(cls / who);
        fs::copy(sourceDir() / "tests/similarity/independent" / who, cls / who,
                 fs::copy_options::recursive);
    }
    // The copies, each disguised another way.
    plant(cls / "kim", cls / "pat", {renamedText});
    plant(cls / "lou", cls / "quinn", {reordered});
    plant(cls / "ada", cls / "ray", {recommented});
    plant(cls / "lou", cls / "sam", {renamedText, reordered, recommented});
    plant(cls / "dana", cls / "val", {renamedText, recommented});
    // Someone who handed in the lab untouched: the template is no one's code.
    ASSERT_EQ(runLabgen("--level open --labs " + quote(dir / "open")).exitCode, 0);
    for (const char* who : {"tess", "uma"})
        for (const char* stage : kStages) {
            fs::create_directories(cls / who / stage);
            fs::copy(dir / "open" / stage, cls / who / stage, fs::copy_options::recursive);
        }

    CommandResult r = runRaylab("similarity --submissions " + quote(cls) +
                                " --stages 01,04,f3 --level open --out " + quote(dir / "out"));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    const std::set<std::string> planted = {"kim,pat", "lou,quinn", "ada,ray",
                                           "lou,sam", "quinn,sam", "dana,val"};
    for (const char* stage : kStages) {
        std::map<std::string, double> scores;
        const auto pairs = flaggedPairs(dir / "out" / "pairs.csv", stage, &scores);
        // The figures docs/grading.md quotes ("Copied code").
        double lowestPlanted = 1.0, highestIndependent = 0.0;
        for (const auto& [pair, score] : scores)
            if (planted.count(pair)) lowestPlanted = std::min(lowestPlanted, score);
            else highestIndependent = std::max(highestIndependent, score);
        std::printf("[ figure   ] %s: planted copies score %.3f at the lowest, independent "
                    "solutions %.3f at the highest\n",
                    stage, lowestPlanted, highestIndependent);
        // Who has the stage: 12 students 01 and 04, 8 f3 (kim and lou wrote no f3, bea only f3).
        const std::size_t n = std::string(stage) == "f3-fins" ? 8 : 12;
        EXPECT_EQ(pairs.size(), n * (n - 1) / 2) << stage << ": every pair of " << n;
        for (const auto& [pair, flagged] : pairs)
            EXPECT_EQ(flagged, planted.count(pair) > 0) << stage << ": " << pair;
        EXPECT_TRUE(fs::is_regular_file(dir / "out" / (std::string(stage) + ".html")));
        // The report shows a flagged pair side by side, the shared code marked.
        const std::string html = readFile(dir / "out" / (std::string(stage) + ".html"));
        EXPECT_NE(html.find("ray.glsl"), std::string::npos) << stage;
        EXPECT_NE(html.find("highlight-red"), std::string::npos) << stage;
    }
    EXPECT_NE(r.out.find("14 pairs at or above 0.85"), std::string::npos) << r.out;
    EXPECT_FALSE(flaggedPairs(dir / "out" / "pairs.csv", "04-recursion").at("tess,uma"))
        << "two untouched labs share only the template";
}

TEST(Similarity, BadRequestsAreOneLineErrorsAndWriteNothing) {
    ScratchDir dir;
    writeSolvedLabs(dir / "one" / "ada");
    fs::create_directories(dir / "two" / "a");
    fs::create_directories(dir / "two" / "b");
    const struct {
        std::string args;
        const char* expected;
    } cases[] = {
        {"--submissions " + quote(dir / "none"), "not a folder"},
        {"--submissions " + quote(dir / "one"), "fewer than two student folders"},
        {"--submissions " + quote(dir / "two"), "no stage has the files of two students"},
        {"--submissions " + quote(dir / "one") + " --threshold 2", "--threshold must be"},
        {"--submissions " + quote(dir / "one") + " --level expert", "unknown level"},
    };
    for (const auto& c : cases) {
        CommandResult r = runRaylab("similarity " + c.args + " --out " + quote(dir / "out"));
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.all();
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(fs::exists(dir / "out")) << c.args;
    }
}
