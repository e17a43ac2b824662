#include "course_file.h"

#include <cstdio>

#include "error.h"
#include "json_reader.h"
#include "paths.h"
#include "stage_list.h"

#include <algorithm>

#include <cmath>
#include <ctime>

namespace raylab {

namespace fs = std::filesystem;

std::optional<std::int64_t> LatePolicy::deadlineOf(const std::string& stage) const {
    auto it = deadlines.find(stage);
    if (it != deadlines.end()) return it->second;
    return deadline;
}

int LatePolicy::daysLate(const std::string& stage, std::int64_t submitted) const {
    return daysLate(deadlineOf(stage), submitted);
}

int LatePolicy::daysLate(std::optional<std::int64_t> due, std::int64_t submitted) const {
    if (!due) return 0;
    const double late = double(submitted - *due) - graceMinutes * 60.0;
    return late > 0.0 ? int(std::ceil(late / 86400.0)) : 0;
}

double LatePolicy::penaltyPercent(const std::string& stage, std::int64_t submitted) const {
    return penaltyForDays(daysLate(stage, submitted));
}

double LatePolicy::penaltyForDays(int days) const {
    return std::min(maxPenalty, penaltyPerDay * double(days));
}

bool StudentException::covers(const std::string& who, const std::string& stage) const {
    return who == student &&
           (stages.empty() || std::find(stages.begin(), stages.end(), stage) != stages.end());
}

namespace {

const StudentException* firstCovering(const std::vector<StudentException>& list,
                                      const std::string& student, const std::string& stage) {
    for (const StudentException& e : list)
        if (e.covers(student, stage)) return &e;
    return nullptr;
}

}  // namespace

const StudentException* CourseSettings::extensionOf(const std::string& student,
                                                    const std::string& stage) const {
    return firstCovering(extensions, student, stage);
}

const StudentException* CourseSettings::excuseOf(const std::string& student,
                                                 const std::string& stage) const {
    return firstCovering(excused, student, stage);
}

std::optional<std::int64_t> CourseSettings::deadlineFor(const std::string& student,
                                                        const std::string& stage) const {
    if (!late) return std::nullopt;
    std::optional<std::int64_t> due = late->deadlineOf(stage);
    const StudentException* e = extensionOf(student, stage);
    if (!due || !e) return due;
    return e->until ? std::max(*due, *e->until) : *due + e->extraSeconds;
}

const StageGrading& CourseSettings::gradingOf(const StageInfo& stage) const {
    auto it = grading.find(stage.id);
    return it == grading.end() ? stage.grading : it->second;
}

namespace {

int digits(const std::string& s, std::size_t at, std::size_t count, const std::string& what) {
    if (at + count > s.size()) throw Error(what);
    int v = 0;
    for (std::size_t i = at; i < at + count; ++i) {
        if (s[i] < '0' || s[i] > '9') throw Error(what);
        v = v * 10 + (s[i] - '0');
    }
    return v;
}

}  // namespace

std::int64_t parseIsoTime(const std::string& text, const std::string& where) {
    const std::string what = where + ": '" + text +
                             "' is not a time like 2026-12-10T23:59:00+01:00 (ISO 8601, with a "
                             "zone: Z or +HH:MM)";
    // YYYY-MM-DDTHH:MM[:SS](Z|+HH:MM|-HH:MM); a space may stand for the T.
    if (text.size() < 17 || text[4] != '-' || text[7] != '-' ||
        (text[10] != 'T' && text[10] != ' ') || text[13] != ':')
        throw Error(what);
    std::tm tm{};
    tm.tm_year = digits(text, 0, 4, what) - 1900;
    tm.tm_mon = digits(text, 5, 2, what) - 1;
    tm.tm_mday = digits(text, 8, 2, what);
    tm.tm_hour = digits(text, 11, 2, what);
    tm.tm_min = digits(text, 14, 2, what);
    std::size_t at = 16;
    if (at < text.size() && text[at] == ':') {
        tm.tm_sec = digits(text, at + 1, 2, what);
        at += 3;
        if (at < text.size() && text[at] == '.') {  // fractions of a second: ignored
            ++at;
            while (at < text.size() && text[at] >= '0' && text[at] <= '9') ++at;
        }
    }
    if (tm.tm_mon < 0 || tm.tm_mon > 11 || tm.tm_mday < 1 || tm.tm_mday > 31 || tm.tm_hour > 23 ||
        tm.tm_min > 59 || tm.tm_sec > 60)
        throw Error(what);
    long offset = 0;
    if (at < text.size() && (text[at] == 'Z' || text[at] == 'z') && at + 1 == text.size()) {
        offset = 0;
    } else if (at + 6 == text.size() && (text[at] == '+' || text[at] == '-') &&
               text[at + 3] == ':') {
        const int hours = digits(text, at + 1, 2, what), mins = digits(text, at + 4, 2, what);
        if (hours > 14 || mins > 59) throw Error(what);  // zones span -12:00 .. +14:00
        const long minutes = hours * 60L + mins;
        offset = (text[at] == '+' ? 1 : -1) * minutes * 60L;
    } else {
        throw Error(what);
    }
    // timegm normalises 30 February to 2 March (in TM too): refuse dates that move.
    const int day = tm.tm_mday, month = tm.tm_mon;
    const std::time_t utc = timegm(&tm);
    if (tm.tm_mday != day || tm.tm_mon != month) throw Error(what);
    return std::int64_t(utc) - offset;
}

std::string formatUtc(std::int64_t seconds) {
    const std::time_t t = std::time_t(seconds);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[40];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
    return buf;
}

namespace {

// "extensions" (WITHTIME: each moves a deadline) or "excused".
std::vector<StudentException> readExceptions(const JsonReader& r, const json& doc, const char* key,
                                             bool withTime) {
    std::vector<StudentException> list;
    if (!doc.contains(key)) return list;
    const json& items = doc[key];
    if (!items.is_array()) r.fail(key, "expected a list of {\"student\": ..., ...}");
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::string where = std::string(key) + "[" + std::to_string(i) + "]";
        const json& item = items[i];
        if (!item.is_object()) r.fail(where, "expected an object");
        if (withTime) r.allowOnly(item, where, {"student", "stages", "days", "until", "reason"});
        else r.allowOnly(item, where, {"student", "stages", "reason"});
        StudentException e;
        if (!item.contains("student"))
            r.fail(where, "no \"student\" (the submission folder's name)");
        e.student = r.string(item["student"], where + ".student");
        if (e.student.empty()) r.fail(where + ".student", "empty");
        if (item.contains("stages")) {
            try {
                e.stages = parseStageIds(r.string(item["stages"], where + ".stages"));
            } catch (const Error& err) { r.fail(where + ".stages", err.what()); }
        }
        if (item.contains("reason")) e.reason = r.string(item["reason"], where + ".reason");
        if (withTime) {
            if (item.contains("days") == item.contains("until"))
                r.fail(where, "give \"days\" (a number of days later) or \"until\" (a time), "
                              "one of them");
            if (item.contains("days")) {
                const json& d = item["days"];
                if (!d.is_number() || d.get<double>() <= 0.0 || d.get<double>() > 365.0)
                    r.fail(where + ".days", "expected a number of days from 0 to 365");
                e.extraSeconds = std::int64_t(std::llround(d.get<double>() * 86400.0));
            } else {
                e.until = parseIsoTime(r.string(item["until"], where + ".until"),
                                       r.file + ": " + where + ".until");
            }
        }
        list.push_back(std::move(e));
    }
    return list;
}

LmsColumns readLmsColumns(const JsonReader& r, const json& lms) {
    if (!lms.is_object()) r.fail("lms", "expected an object");
    r.allowOnly(lms, "lms", {"column_prefix", "canvas_assignments", "blackboard_columns"});
    LmsColumns c;
    if (lms.contains("column_prefix"))
        c.prefix = r.string(lms["column_prefix"], "lms.column_prefix");
    auto ids = [&](const char* key, std::map<std::string, std::string>& into) {
        if (!lms.contains(key)) return;
        const json& m = lms[key];
        const std::string where = std::string("lms.") + key;
        if (!m.is_object()) r.fail(where, "expected an object of stage ids");
        for (auto it = m.begin(); it != m.end(); ++it) {
            if (it.key() == "comment") continue;
            std::string id;
            try {
                id = findStage(it.key()).id;
            } catch (const Error& e) { r.fail(where + "." + it.key(), e.what()); }
            const json& v = it.value();
            std::string text = v.is_number_unsigned() ? std::to_string(v.get<std::uint64_t>())
                               : v.is_string()        ? v.get<std::string>()
                                                      : "";
            if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
                r.fail(where + "." + it.key(), "expected the LMS's numeric id (12345)");
            into[id] = text;
        }
    };
    ids("canvas_assignments", c.canvasAssignments);
    ids("blackboard_columns", c.blackboardColumns);
    return c;
}

}  // namespace

CourseSettings readCourseFile(const fs::path& file) {
    const std::string shown = displayPath(file);
    const JsonReader r{shown};
    const json doc = parseJsonFile(file, shown);
    if (!doc.is_object()) r.fail("(top level)", "expected an object");
    r.allowOnly(doc, "", {"earlier_stages", "stages", "late", "extensions", "excused", "lms"});
    CourseSettings c;
    c.file = file;
    if (doc.contains("earlier_stages")) {
        const json& e = doc["earlier_stages"];
        if (!e.is_string()) r.fail("earlier_stages", "expected \"solved\" or \"own\"");
        c.earlierStages = parseEarlierStages(e.get<std::string>(), shown + ": earlier_stages");
    }
    if (doc.contains("stages")) {
        const json& stages = doc["stages"];
        if (!stages.is_object()) r.fail("stages", "expected an object of stage ids");
        for (auto it = stages.begin(); it != stages.end(); ++it) {
            if (it.key() == "comment") continue;
            const std::string where = "stages." + it.key();
            const StageInfo* stage = nullptr;
            try {
                stage = &findStage(it.key());
            } catch (const Error& e) { r.fail(where, e.what()); }
            r.allowOnly(it.value(), where, {"grading"});
            if (!it.value().contains("grading")) continue;
            StageGrading g =
                readGrading(r, it.value()["grading"], where + ".grading", stage->grading);
            validateGrading(g, *stage, shown + ": " + where + ".grading");
            c.grading[stage->id] = g;
        }
    }
    if (doc.contains("late")) {
        const json& late = doc["late"];
        if (!late.is_object()) r.fail("late", "expected an object");
        r.allowOnly(late, "late",
                    {"deadline", "deadlines", "grace_minutes", "penalty_per_day", "max_penalty"});
        LatePolicy p;
        auto time = [&](const json& v, const std::string& where) {
            return parseIsoTime(r.string(v, where), shown + ": " + where);
        };
        if (late.contains("deadline")) p.deadline = time(late["deadline"], "late.deadline");
        if (late.contains("deadlines")) {
            const json& d = late["deadlines"];
            if (!d.is_object()) r.fail("late.deadlines", "expected an object of stage ids");
            for (auto it = d.begin(); it != d.end(); ++it) {
                if (it.key() == "comment") continue;
                const std::string where = "late.deadlines." + it.key();
                std::string id;
                try {
                    id = findStage(it.key()).id;
                } catch (const Error& e) { r.fail(where, e.what()); }
                p.deadlines[id] = time(it.value(), where);
            }
        }
        auto percent = [&](const char* key, double fallback) {
            if (!late.contains(key)) return fallback;
            const json& v = late[key];
            if (!v.is_number() || v.get<double>() < 0.0 || v.get<double>() > 100.0)
                r.fail(std::string("late.") + key, "expected a percentage from 0 to 100");
            return v.get<double>();
        };
        p.penaltyPerDay = percent("penalty_per_day", 0.0);
        p.maxPenalty = percent("max_penalty", 100.0);
        if (late.contains("grace_minutes")) {
            const json& v = late["grace_minutes"];
            if (!v.is_number() || v.get<double>() < 0.0 || v.get<double>() > 100000.0)
                r.fail("late.grace_minutes", "expected minutes from 0 to 100000");
            p.graceMinutes = v.get<double>();
        }
        if (!p.deadline && p.deadlines.empty())
            r.fail("late", "a late policy needs a deadline (\"deadline\" or \"deadlines\")");
        c.late = p;
    }
    c.extensions = readExceptions(r, doc, "extensions", true);
    c.excused = readExceptions(r, doc, "excused", false);
    if (!c.extensions.empty() && !c.late)
        r.fail("extensions", "extensions move deadlines: the course file has no late policy");
    if (doc.contains("lms")) c.lms = readLmsColumns(r, doc["lms"]);
    return c;
}

std::string courseRulesSection(const StageInfo& stage, const CourseSettings& course) {
    if (course.file.empty()) return "";
    auto number = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", v);
        return std::string(buf);
    };
    std::string t;
    if (course.late) {
        const LatePolicy& p = *course.late;
        const std::optional<std::int64_t> due = p.deadlineOf(stage.id);
        if (!due) {
            t += "**Deadline:** none for this stage in your course.\n";
        } else {
            t += "**Deadline:** " + formatUtc(*due) + ".";
            if (p.penaltyPerDay > 0)
                t += " Work handed in later loses " + number(p.penaltyPerDay) +
                     "% of the score it earned for every day or part of a day past it" +
                     (p.graceMinutes > 0 ? " (after " + number(p.graceMinutes) + " minutes' grace)"
                                         : "") +
                     ", at most " + number(p.maxPenalty) + "%.";
            t += "\n";
        }
    }
    if (!stage.buildsOn.empty())
        t += std::string("**Earlier stages:** ") +
             (course.earlierStages == EarlierStages::Solved
                  ? "this stage is graded with the stages it builds on solved, so a slip in an "
                    "earlier stage costs points there only (`raylab check` draws your own: "
                    "where one of them fails, it says so first).\n"
                  : "this stage is graded with your own earlier stages, as `raylab check` draws "
                    "it: a slip in an earlier stage costs points here too.\n");
    return t;
}

}  // namespace raylab
