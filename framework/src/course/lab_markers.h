#pragma once
// The marker convention that makes labs/ a pure function of solution/.
// Instructors need it; students only ever see its output.
//
// In a solution file, a region a student must write looks like
//
//     // TODO(01.a): what to do, for the student      <- header: comment lines
//     // Checked by: raylab check --stage 01
//     //@solution
//     ...the solution code...
//     //@stub
//     //@ labTodo();                                  <- stub code, behind "//@ "
//     //@ return NO_HIT;
//     //@end
//
// The lab form keeps the header and puts the stub code in place of the
// solution; the solved form (what later stages' labs include) keeps only the
// solution code.
//
// Two levels of lab come from one file. The guided level (today's labs)
// leaves the algorithm's structure in place and asks for a line or two per
// TODO; the open level removes whole function bodies (or whole shaders).
// An open region wraps what the open level takes away:
//
//     //@open
//     //@ // TODO(01.a): the contract: inputs, outputs, units, edge cases
//     //@ // Checked by: raylab check --stage 01 (intersectSphere; all views)
//     //@ labTodo();                                  <- the open level's stub
//     //@ return NO_HIT;
//     //@guided
//     ...the guided level's text: given code, TODO headers and
//        //@solution ... //@end regions...
//     //@end-open
//
// The open lab keeps only the stub (behind "//@ ", as above); the guided lab
// and the solved form treat the guided part as if the region were not there.
#include <string>
#include <vector>

namespace raylab {

enum class MarkedForm { Lab, Solved };

// How much of the algorithm a lab hands out (course/lab_markers.h above).
enum class Level { Guided, Open };

// "guided" or "open"; throws Error otherwise.
Level parseLevel(const std::string& name);
const char* levelName(Level level);

// Throws Error("FILE:LINE: ...") on a malformed region. LEVEL matters only to
// the lab form (the solved form is the same at both levels).
std::string transformMarkedSource(const std::string& text, MarkedForm form,
                                  const std::string& fileForMessages, Level level = Level::Guided);

// The 1-based numbers of TEXT's solution lines (those between "//@solution"
// and "//@stub"): the code students write, which `raylab mutants` mutates.
// Does not validate the markers (transformMarkedSource does).
std::vector<int> solutionLineNumbers(const std::string& text);

// How many lines of code a student writes in TEXT at LEVEL: the solved
// lines the lab form takes away, blank lines and comment-only lines not
// counted. Assumes valid markers (run transformMarkedSource first).
int studentCodeLines(const std::string& text, Level level);

}  // namespace raylab
