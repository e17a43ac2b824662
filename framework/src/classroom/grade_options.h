#pragma once
// What `raylab grade` is asked to do (its options, cli/cmd_grade.cpp), as the
// class workflow (this module) takes it: the class, the limits every item
// runs under, and the course's workflow (course file, times, roster, LMS,
// pseudonyms, a regrade of one student).
#include <string>

namespace raylab {

struct GradeOptions {
    std::string submissions;  // one folder per student, each laid out like labs/
    std::string outDir;
    std::string stages;  // "01,02,04"; empty: every available stage
    int jobs = 2;
    double timeoutSeconds = 60.0;  // per stage of a submission
    long memoryMb =
        2048;  // per stage of a submission (address space); the pro scene needs well under 1 GB
    unsigned seed = 0;  // of the seeded views; keep it secret to prevent tuning
    std::string shard;  // "K/N": grade that share of the class only (grade_shards.h)
    // The course's workflow (class_finish.h):
    std::string course;     // --course FILE: weights over stage.json's, a late policy
    std::string submitted;  // --submitted CSV|mtime: when each student submitted
    std::string roster;     // --roster CSV: ids (summary.csv) and what an LMS needs
    std::string lms;  // --lms canvas,moodle,blackboard,brightspace: OUT/<lms>.csv (lms_exports.h)
    std::string anonymise;  // --anonymise KEYFILE: pseudonyms (pseudonyms.h) in every report file
    std::string only;       // --only NAME: regrade one student into OUT's report
    std::string reason;     // --reason TEXT: why (the regrade's log)
    std::string level = "guided";  // --level: of the labs handed out (lab_folder.h)
};

}  // namespace raylab
