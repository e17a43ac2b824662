// libFuzzer target: raylab::transformMarkedSource, the //@solution ... //@end
// marker parser, in both forms (lab and solved) at both levels (guided, open). Pure string
// processing: no files are read or written.
#include "error.h"
#include "lab_markers.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace {
std::size_t lineCount(const std::string& s) {  // lines as std::getline sees them
    std::size_t n = 0;
    for (char c : s) n += c == '\n';
    return n + (!s.empty() && s.back() != '\n');
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raylab;
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (MarkedForm form : {MarkedForm::Lab, MarkedForm::Solved})
        for (Level level : {Level::Guided, Level::Open}) {
            try {
                std::string out = transformMarkedSource(text, form, "fuzz.glsl", level);
                // Every output line is one input line (possibly shortened): never more lines out
                // than in.
                if (lineCount(out) > lineCount(text)) __builtin_trap();
            } catch (const Error&) {
                // Malformed region: the expected rejection.
            }
        }
    return 0;
}
