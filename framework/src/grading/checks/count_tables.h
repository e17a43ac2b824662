#pragma once
// The count checks' CPU figures as data: for each view of a stage that a
// count check applies to, the number its GPU must produce (fin_count: the
// mesh's silhouette edges, sure and edge-on, silhouette.h). A build without
// the references (the page's core, a student repository) measures the GPU's
// number only and judges it against these, so it holds no silhouette test
// (TODO f3.a's answer). They travel in the function tables' file, under
// "counts" (function_tables.h; `raylab function-tables` writes both).
#include "fin_count.h"
#include "stage_catalog.h"
#include "track_renderer.h"

#include <nlohmann/json_fwd.hpp>

#include <map>
#include <string>
#include <vector>

namespace raylab {

struct KnownCount {
    long outOf = 0;  // the mesh's edges: a table written for another mesh is noticed
    SilhouetteCount count;
};
// "stage/check/view" -> its count.
using CountTables = std::map<std::string, KnownCount>;

#ifndef RAYLAB_REFERENCES_AS_DATA
// STAGES' count checks over their check views as the file's "counts" object
// (native only: it runs the silhouette count).
nlohmann::json countTablesJson(const std::vector<const StageInfo*>& stages);
#endif

// The "counts" object of the tables' text TEXT (from FILE, for messages);
// none when it has no "counts". Throws Error naming FILE when malformed.
CountTables parseCountTables(const std::string& text, const std::string& file);

// MEASURED (a CountResult with measuredOnly) judged against the table's
// count for STAGE's CHECK in VIEW. Throws Error naming FILE when the table
// has none (a bundle without the stage, a seeded view) or was written for
// another mesh.
CountResult judgedByTable(const CountTables& tables, const std::string& file,
                          const std::string& stage, const std::string& check,
                          const std::string& view, CountResult measured);

// The count tables of kTablesAsData (function_tables.h), read once.
const CountTables& countTablesAsData();

}  // namespace raylab
