#pragma once
// Whole-file text writes that are atomic: the text goes to FILE.tmp-PID in the
// same folder, is flushed to disk, and only then renamed over FILE. A failed
// or interrupted write never leaves a partial file under the real name.
#include <filesystem>
#include <string>

namespace raylab {

// Replaces FILE (or creates it) with TEXT. The folder must exist. On any
// failure the temporary file is removed, FILE is left as it was, and
// Error("cannot write FILE: reason") is thrown.
void writeTextFileAtomic(const std::filesystem::path& file, const std::string& text);

}  // namespace raylab
