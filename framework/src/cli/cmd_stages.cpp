#include "command.h"
#include "commands.h"

#include <cstdio>

namespace raylab {

int cmdStages() {
    std::string track;
    for (const StageInfo& s : allStages()) {
        if (s.track != track) {
            track = s.track;
            std::printf("%strack %s\n", &s == &allStages().front() ? "" : "\n", track.c_str());
        }
        std::printf("  %-14s %s\n", s.id.c_str(), s.title.c_str());
    }
    return 0;
}

Command stagesCommand() {
    return {"stages", "list the stages of the course",
            [](CLI::App&) { return std::function<int()>(cmdStages); }};
}

}  // namespace raylab
