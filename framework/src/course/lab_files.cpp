#include "lab_files.h"

#include "paths.h"
#include "shader_source.h"
#include "stage_sources.h"

namespace raylab {

namespace fs = std::filesystem;

std::map<std::string, LabFile> labFileSources(const StageInfo& stage) {
    StageSources sources = solutionSources(stage);
    const fs::path own = fs::weakly_canonical(projectRoot() / "solution" / stage.id);
    const fs::path framework = projectRoot() / "framework";
    std::map<std::string, LabFile> files;
    std::vector<std::string> entries;
    for (const auto& [key, program] : stage.allPrograms())
        entries.insert(entries.end(), {program->vertex, program->geometry, program->fragment});
    for (const std::string& entry : entries) {
        if (entry.empty()) continue;
        ShaderSource src = assembleShader(entry, sources.search, stage.defines());
        for (const fs::path& f : src.files) {
            fs::path canonical = fs::weakly_canonical(f);
            if (canonical.lexically_relative(framework).begin()->string() != "..") continue;
            files[f.filename().string()] = {f, canonical.parent_path() == own};
        }
    }
    return files;
}

std::map<std::string, std::string> labFiles(const StageInfo& stage, MarkedForm formOfOwnFiles,
                                            Level level) {
    std::map<std::string, std::string> files;
    for (const auto& [name, file] : labFileSources(stage))
        files[name] = transformMarkedSource(readTextFile(file.source),
                                            file.own ? formOfOwnFiles : MarkedForm::Solved,
                                            displayPath(file.source), level);
    return files;
}

}  // namespace raylab
