#include "count_tables.h"

#include "error.h"
#include "function_tables.h"
#include "paths.h"

#ifndef RAYLAB_REFERENCES_AS_DATA
#include "adjacency.h"
#include "fur_scene.h"
#include "json_reader.h"
#include "silhouette.h"
#endif

#include <nlohmann/json.hpp>

namespace raylab {

using nlohmann::json;

#ifndef RAYLAB_REFERENCES_AS_DATA
json countTablesJson(const std::vector<const StageInfo*>& stages) {
    json counts = json::object();
    for (const StageInfo* stage : stages)
        for (const std::string& check : stage->countChecks) {
            if (check != "fin_count") continue;  // the only count check (stage_catalog.cpp)
            for (const CheckView& view : stage->checkViews) {
                if (!view.fins || view.furTechnique != 0) continue;  // FurRenderer::countCheck
                // The view as ViewRenderers draws it: its scene, its camera.
                const auto file = stage->sceneFileOf(view);
                const FurScene scene = loadFurScene(file);
                const Mesh mesh = loadFurMesh(scene);
                const EdgeAdjacency adjacency = buildEdgeAdjacency(mesh);
                const glm::dvec3 eye =
                    view.pose ? view.pose->position : loadSceneCamera(file).pose.position;
                const SilhouetteCount c = countSilhouettes(
                    mesh, adjacency, glm::dmat4(scene.modelMatrix(view.time)), eye);
                counts[stage->id][check][view.name] = {{"edges", adjacency.edgeCount()},
                                                       {"certain", c.certain},
                                                       {"uncertain", c.uncertain}};
            }
        }
    return counts;
}
#endif

CountTables parseCountTables(const std::string& text, const std::string& file) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception& e) { throw Error(file + ": not JSON: " + e.what()); }
    CountTables tables;
    if (!doc.is_object() || !doc.contains("counts")) return tables;
    const json& counts = doc["counts"];
    auto objectAt = [&](const json& j, const std::string& where) {
        if (!j.is_object()) throw Error(file + ": " + where + ": expected an object");
    };
    objectAt(counts, "counts");
    for (const auto& [stage, checks] : counts.items()) {
        objectAt(checks, "counts." + stage);
        for (const auto& [check, views] : checks.items()) {
            objectAt(views, "counts." + stage + "." + check);
            for (const auto& item : views.items()) {
                // (Not a structured binding: C++17 lambdas cannot capture one.)
                const std::string& view = item.key();
                const json& entry = item.value();
                const std::string where = "counts." + stage + "." + check + "." + view;
                auto whole = [&](const char* key) {
                    if (!entry.is_object() || !entry.contains(key) ||
                        !entry[key].is_number_integer() || entry[key].get<long>() < 0)
                        throw Error(file + ": " + where +
                                    ": expected {\"edges\", \"certain\", "
                                    "\"uncertain\"} as whole numbers");
                    return entry[key].get<long>();
                };
                KnownCount& k = tables[stage + "/" + check + "/" + view];
                k.outOf = whole("edges");
                k.count.certain = whole("certain");
                k.count.uncertain = whole("uncertain");
            }
        }
    }
    return tables;
}

CountResult judgedByTable(const CountTables& tables, const std::string& file,
                          const std::string& stage, const std::string& check,
                          const std::string& view, CountResult measured) {
    const auto it = tables.find(stage + "/" + check + "/" + view);
    if (it == tables.end())
        throw Error(file + " has no " + check + " for view " + view + " of " + stage +
                    " (it holds the released stages' own views only)");
    if (it->second.outOf != measured.outOf)
        throw Error(file + ": " + check + " of " + stage + " view " + view + " was written for " +
                    std::to_string(it->second.outOf) + " edges, the mesh here has " +
                    std::to_string(measured.outOf));
    const FinCountVerdict v =
        judgeFinCount(measured.measured, std::size_t(measured.outOf), it->second.count);
    measured.passed = v.passed;
    measured.detail = v.detail;
    measured.measuredOnly = false;
    return measured;
}

const CountTables& countTablesAsData() {
    static const CountTables tables =
        parseCountTables(readTextFile(projectRoot() / kTablesAsData), kTablesAsData);
    return tables;
}

}  // namespace raylab
