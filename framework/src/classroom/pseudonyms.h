#pragma once
// Pseudonyms for anonymised reports (`raylab grade --anonymise KEYFILE`): a
// keyed hash (BLAKE2b, Debian's libsodium) of the student's folder name under
// a random key kept in KEYFILE, outside the report. The same key gives the
// same pseudonyms in every run; without it a pseudonym cannot be worked back
// from a list of names (a hash of the name alone, or of the name and the
// grading seed, could). KEYFILE also keeps which pseudonym is whose, for the
// instructor:
//   {"comment": "...", "key": "<64 hex digits>", "pseudonyms": {"student-3f9a2c1e": "alice"}}
#include <filesystem>
#include <map>
#include <string>

namespace raylab {

class PseudonymKey {
public:
    // Reads KEYFILE, or makes a new key when it does not exist (written by
    // save()). Throws Error on a file that is not one.
    explicit PseudonymKey(const std::filesystem::path& keyFile);
    // "student-" and 8 hex digits; remembered for save().
    std::string pseudonym(const std::string& name);
    // The folder name behind a pseudonym this file knows, or "".
    std::string nameOf(const std::string& pseudonym) const;
    const std::map<std::string, std::string>& known() const { return names_; }
    void save() const;  // KEYFILE, written whole, readable by its owner only

private:
    std::filesystem::path file_;
    std::string key_;                           // 32 bytes
    std::map<std::string, std::string> names_;  // pseudonym -> folder name
};

// TEXT with the student's folder under SUBMISSIONS (as given, absolute,
// canonical) and NAME replaced by PSEUDONYM: compiler messages and logs
// name the student's files.
std::string withoutName(std::string text, const std::string& name, const std::string& pseudonym,
                        const std::filesystem::path& submissions);

// TEXT with the student's folder under SUBMISSIONS (as given, absolute,
// canonical) written as NAME/ alone: what a student sees never shows the
// grading machine's folders ("alice/01-raycast/shade.glsl:12", not
// "/scratch/job-4411/class/alice/01-raycast/shade.glsl:12").
std::string withoutMachinePath(std::string text, const std::string& name,
                               const std::filesystem::path& submissions);

// withoutName (or withoutMachinePath when PSEUDONYM is NAME) for the text
// file LOG, rewritten whole when anything changed.
void scrubNames(const std::filesystem::path& log, const std::string& name,
                const std::string& pseudonym, const std::filesystem::path& submissions);

}  // namespace raylab
