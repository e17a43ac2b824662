#include "class_finish.h"

#include "check_report.h"

#include "mistake_catalog.h"
#include "stage_catalog.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace raylab {

void applyCourseRules(ClassResult& result, const CourseSettings& course,
                      const SubmissionTimes* times,
                      const std::map<std::string, std::string>& folderOf) {
    std::vector<std::string> untimed;  // said on the console: a misspelt name escapes the policy
    for (StudentResult& st : result.students) {
        auto folder = folderOf.find(st.name);
        const std::string name = folder == folderOf.end() ? st.name : folder->second;
        for (StageResult& s : st.stages) {
            s.latePenalty = 0;
            s.lateNote.clear();
            s.excused = false;
            s.excuseNote.clear();
            if (const StudentException* e = course.excuseOf(name, s.stage)) {
                s.excused = true;
                s.excuseNote = e->reason.empty() ? "excused by the course file" : e->reason;
                continue;
            }
            const std::optional<std::int64_t> due = course.deadlineFor(name, s.stage);
            if (s.status == "not submitted" || !course.late || !due || !times) continue;
            const StudentException* extension = course.extensionOf(name, s.stage);
            const std::string extended =
                extension ? "extended to " + formatUtc(*due) +
                                (extension->reason.empty() ? "" : " (" + extension->reason + ")")
                          : "";
            const std::optional<std::int64_t> when = times->of(name, s.stage);
            if (!when) {
                s.lateNote = "no submission time in " + times->source() + ": taken as on time";
                untimed.push_back(st.name + " " + s.stage);
                continue;
            }
            const int days = course.late->daysLate(due, *when);
            if (days == 0) {
                s.lateNote = extended.empty() ? "" : "on time, " + extended;
                continue;
            }
            const double percent = course.late->penaltyForDays(days);
            const double raw = s.score;
            s.latePenalty = std::round(raw * percent) / 100.0;
            s.score = std::round((raw - s.latePenalty) * 100.0) / 100.0;
            char note[160];
            std::snprintf(note, sizeof note, "submitted %s, %d day%s late: -%g%%, %g instead of %g",
                          formatUtc(*when).c_str(), days, days == 1 ? "" : "s", percent, s.score,
                          raw);
            s.lateNote = note + (extended.empty() ? "" : " (" + extended + ")");
        }
    }
    if (!untimed.empty())
        std::fprintf(stderr,
                     "raylab grade: %zu graded stage%s no submission time in %s (taken as on "
                     "time): %s\n",
                     untimed.size(), untimed.size() == 1 ? " has" : "s have",
                     times->source().c_str(), firstFew(untimed).c_str());
}

std::vector<std::string> attachRoster(ClassResult& result,
                                      const std::map<std::string, RosterEntry>& roster) {
    std::vector<std::string> unlisted;
    std::set<std::string> seen;
    for (StudentResult& st : result.students) {
        seen.insert(st.name);
        auto it = roster.find(st.name);
        if (it == roster.end()) unlisted.push_back(st.name);
        else st.roster = it->second;
    }
    for (const auto& [name, entry] : roster) {
        if (seen.count(name)) continue;
        StudentResult st;
        st.name = name;
        st.roster = entry;
        st.hasFolder = false;
        for (const std::string& id : result.stages) {
            StageResult s;
            s.stage = id;
            s.status = "not submitted";
            s.message = "in the roster, but no submission folder";
            st.stages.push_back(s);
        }
        result.students.push_back(std::move(st));
    }
    std::sort(result.students.begin(), result.students.end(),
              [](const StudentResult& a, const StudentResult& b) { return a.name < b.name; });
    return unlisted;
}

void matchMistakes(ClassResult& result) {
    result.mistakes.clear();
    for (const std::string& id : result.stages) {
        const StageInfo& stage = findStage(id);
        // Mistakes that fail the same checks and name the same causes look
        // alike in any report: one row, listed once.
        std::vector<MistakeMatch> rows;
        for (const CatalogMistake& m : stageMistakes(stage)) {
            auto it = std::find_if(rows.begin(), rows.end(), [&](const MistakeMatch& r) {
                return r.checks == m.caughtBy && r.hints == m.hints;
            });
            if (it == rows.end()) {
                rows.push_back({m.stage, m.name, m.description, m.central, m.caughtBy, 0, m.hints});
                continue;
            }
            it->name += ", " + m.name;
            it->description += "; or " + m.description;
            it->central = it->central || m.central;
        }
        for (const StudentResult& st : result.students)
            for (const StageResult& s : st.stages) {
                if (s.stage != id || s.status != "graded") continue;
                std::vector<std::string> failed;
                std::string outputs;
                for (const CheckResult& c : s.checks) {
                    if (c.seeded) continue;
                    if (!c.passed) failed.push_back(c.name);
                    outputs += c.output + "\n";
                }
                std::sort(failed.begin(), failed.end());
                // The failing checks and the causes their hints name (the
                // function checks' diagnoses read the failing cases).
                const std::vector<std::string> causes = causesNamed(outputs, stage);
                for (MistakeMatch& row : rows)
                    if (failed == row.checks && causes == row.hints) ++row.matches;
            }
        for (MistakeMatch& row : rows) result.mistakes.push_back(std::move(row));
    }
}

std::string firstFew(const std::vector<std::string>& names, std::size_t most) {
    std::string list;
    for (std::size_t i = 0; i < names.size() && i < most; ++i) list += (i ? ", " : "") + names[i];
    return names.size() > most ? list + ", ..." : list;
}

}  // namespace raylab
