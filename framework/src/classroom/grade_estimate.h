#pragma once
// `raylab grade --estimate`: what grading the class will cost, from a small
// sample of it graded for real (in a scratch folder, removed afterwards):
// the time per student-stage and the memory of the largest, then the whole
// class's time on this machine with --jobs, per task of a Slurm array of N
// shares, and per upload on Gradescope (half a CPU, one stage at a time),
// and the memory a job needs.
#include "grade_options.h"

#include <string>
#include <vector>

namespace raylab {

struct ItemCost {
    double seconds = 0;  // wall time of its child
    double peakMb = 0;
    bool timedOut = false;
};

struct ClassEstimate {
    std::size_t students = 0, stages = 0;  // of the class
    std::size_t sampled = 0;               // students graded as the sample
    double sampleSeconds = 0;              // the sample's wall time, references included
    double fixedSeconds = 0;               // what a run costs before its first item (references)
    double itemSeconds = 0;                // the mean time per submitted student-stage
    double itemMaxSeconds = 0;
    double submittedShare = 1;  // of the sample's student-stages that had a folder
    double peakMb = 0;
    int jobs = 1;
    double classSeconds() const;                            // this machine, --jobs
    double taskSeconds(int shares, int cpusPerTask) const;  // one task of a Slurm array
    double uploadSeconds() const;  // one student's upload on Gradescope (half a CPU)
};

// The sample: SAMPLE students spread evenly over the sorted folders.
std::vector<std::string> sampleStudents(const std::vector<std::string>& students,
                                        std::size_t sample);

// The estimate from the sample's costs (ITEMS: one per student-stage graded).
ClassEstimate estimateFrom(const std::vector<ItemCost>& items, std::size_t notSubmitted,
                           double sampleSeconds, std::size_t students, std::size_t stages,
                           std::size_t sampled, int jobs);

// Grades the sample of G's class and prints the estimate. Throws Error on
// bad options; returns false when interrupted.
bool estimateClass(const GradeOptions& g, std::size_t sample);

// The estimate as lines for the console.
std::string describeEstimate(const ClassEstimate& e, const GradeOptions& g);

}  // namespace raylab
