#include "commands.h"

#include <cstdio>

namespace raylab {

int cmdStages() {
    for (const StageInfo& s : allStages())
        std::printf("%-14s %s%s\n", s.id.c_str(), s.title.c_str(), s.available() ? "" : "  [not available yet]");
    return 0;
}

} // namespace raylab
