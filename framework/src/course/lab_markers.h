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
#include <string>
#include <vector>

namespace raylab {

enum class MarkedForm { Lab, Solved };

// Throws Error("FILE:LINE: ...") on a malformed region.
std::string transformMarkedSource(const std::string& text, MarkedForm form,
                                  const std::string& fileForMessages);

// The 1-based numbers of TEXT's solution lines (those between "//@solution"
// and "//@stub"): the code students write, which `raylab mutants` mutates.
// Does not validate the markers (transformMarkedSource does).
std::vector<int> solutionLineNumbers(const std::string& text);

}  // namespace raylab
