#include "prairielearn_results.h"

#include "paths.h"

namespace raylab {

namespace fs = std::filesystem;

namespace {

// Pictures in results.json, base64 inside a data URL, within this budget
// (PrairieLearn's limit for the whole file is 1 MB).
constexpr std::size_t kImageBudget = 600 * 1024;

std::string base64(const std::string& bytes) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                           (unsigned char)bytes[i + 2];
        for (int k = 18; k >= 0; k -= 6) out += abc[(v >> k) & 63];
    }
    if (i < bytes.size()) {
        unsigned v = (unsigned char)bytes[i] << 16;
        if (i + 1 < bytes.size()) v |= (unsigned char)bytes[i + 1] << 8;
        out += abc[(v >> 18) & 63];
        out += abc[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? abc[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

}  // namespace

nlohmann::ordered_json prairieLearnResults(const UploadGrade& graded, bool hideSeeded) {
    using Json = nlohmann::ordered_json;
    std::string notes;
    for (const std::string& n : graded.layout.notes) notes += n + "\n";
    const std::string& problem = graded.layout.problem;
    if (!problem.empty())  // not gradable: no attempt is used up
        return Json{{"gradable", false},
                    {"score", 0.0},
                    {"format_errors", Json::array({problem})},
                    {"message", problem},
                    {"output", notes}};
    const StudentResult& st = *graded.student;
    auto shown = [&](const std::string& text) { return graded.shown(text); };
    std::error_code ec;

    Json tests = Json::array();
    std::size_t imageBytes = 0;
    std::string summary;
    for (const StageResult& s : st.stages) {
        summary += (summary.empty() ? "" : "; ") + s.stage + ": " +
                   (s.status == "graded" ? std::to_string(int(s.score + 0.5)) + "/" +
                                               std::to_string(int(s.maxScore + 0.5))
                                         : s.status);
        if (s.status != "graded" || s.checks.empty()) {
            tests.push_back(Json{{"name", s.stage},
                                 {"description", s.status},
                                 {"points", s.score},
                                 {"max_points", s.maxScore},
                                 {"message", shown(s.message.empty() ? s.status : s.message)}});
            continue;
        }
        // PrairieLearn shows every test of results.json at once (its tests
        // have no visibility of their own, unlike Gradescope's). Hidden
        // seeded views are one test: their points count (the score is the
        // grade), but not which view failed, how, or its picture.
        double seededPoints = 0, seededMax = 0;
        int seededCount = 0;
        for (const CheckResult& c : s.checks) {
            if (c.seeded && hideSeeded) {
                seededPoints += c.score;
                seededMax += c.maxScore;
                ++seededCount;
                continue;
            }
            Json t{{"name", s.stage + " / " + c.name},
                   {"description", c.kind == "image" ? "a camera view against the solution"
                                                     : "a function against a reference"},
                   {"points", c.score},
                   {"max_points", c.maxScore},
                   {"message", shown(c.output)}};
            // The difference heat map of a failed view, while the budget lasts.
            if (!c.passed && !c.diffImage.empty()) {
                const fs::path png = graded.outDir / c.diffImage;
                if (fs::is_regular_file(png, ec)) {
                    const std::string url = "data:image/png;base64," + base64(readTextFile(png));
                    if (imageBytes + url.size() <= kImageBudget) {
                        imageBytes += url.size();
                        t["images"] = Json::array(
                            {Json{{"label", c.name + ": difference (black equal, red most)"},
                                  {"url", url}}});
                    }
                }
            }
            tests.push_back(t);
        }
        if (seededCount > 0)
            tests.push_back(
                Json{{"name", s.stage + " / " + std::to_string(seededCount) + " further views"},
                     {"description", "camera views moved a little from the check views"},
                     {"points", seededPoints},
                     {"max_points", seededMax},
                     {"message", "Which of these views differ, and how, is shown after the due "
                                 "date: the views are drawn from the course's secret seed, so "
                                 "that a lab passes them by being right, not by matching a "
                                 "picture."}});
    }
    const double max = st.maxScore();
    return Json{{"gradable", true},
                {"score", max > 0 ? st.score() / max : 0.0},
                {"message", "Total " + std::to_string(int(st.score() + 0.5)) + " / " +
                                std::to_string(int(max + 0.5)) + ". " + summary},
                {"output", notes},
                {"tests", tests}};
}

}  // namespace raylab
