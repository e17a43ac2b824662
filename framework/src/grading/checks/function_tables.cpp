#include "function_tables.h"

#include "count_tables.h"

#include "error.h"
#include "paths.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace raylab {

using nlohmann::json;

namespace {

#ifndef RAYLAB_REFERENCES_AS_DATA
// JSON has no NaN or infinity: those values are written as text. (Only the
// instructors' build writes the tables.)
json number(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
}
#endif

double numberFrom(const json& v, const std::string& where) {
    if (v.is_number()) return v.get<double>();
    if (v == "nan") return std::nan("");
    if (v == "inf") return INFINITY;
    if (v == "-inf") return -INFINITY;
    throw Error(where + ": expected a number, \"nan\", \"inf\" or \"-inf\"");
}

}  // namespace

#ifndef RAYLAB_REFERENCES_AS_DATA
std::string functionTablesJson() {
    std::vector<const FunctionSpec*> specs;
    for (const FunctionSpec& spec : functionSpecs()) specs.push_back(&spec);
    std::vector<const StageInfo*> stages;
    for (const StageInfo& stage : allStages()) stages.push_back(&stage);
    return functionTablesJson(specs, stages);
}

std::string functionTablesJson(const std::vector<const FunctionSpec*>& chosen,
                               const std::vector<const StageInfo*>& stages) {
    // One line per case (compact, yet a changed case shows as one line in a diff).
    std::string text = "{\"about\": \"the function checks' inputs and expected values, and "
                       "their harness GLSL; the count checks' CPU figures for the stages' "
                       "views (raylab function-tables)\",\n \"functions\": {";
    bool firstSpec = true;
    for (const FunctionSpec* spec : chosen) {
        const std::vector<glm::dvec4> wants = referenceWants(*spec);
        text += std::string(firstSpec ? "\n" : ",\n") + "  " + json(spec->name).dump() + ": {\n";
        firstSpec = false;
        text += "   \"prelude\": " + json(spec->prelude).dump() + ",\n";
        text += "   \"helpers\": " + json(spec->helpers).dump() + ",\n";
        text += "   \"cases\": [\n";
        for (std::size_t i = 0; i < spec->cases.size(); ++i) {
            json in = json::array();
            for (const glm::dvec4& a : spec->cases[i].in)
                in.push_back({number(a.x), number(a.y), number(a.z), number(a.w)});
            json c = {
                {"case", spec->cases[i].label},
                {"in", in},
                {"want",
                 {number(wants[i].x), number(wants[i].y), number(wants[i].z), number(wants[i].w)}}};
            if (spec->cases[i].hitOrMiss) c["either"] = true;
            text += "    " + c.dump() + (i + 1 < spec->cases.size() ? ",\n" : "\n");
        }
        text += "   ]\n  }";
    }
    text += std::string(chosen.empty() ? "" : "\n ") + "},\n \"counts\": {";
    bool firstStage = true;
    const json counts = countTablesJson(stages);
    for (const auto& [stage, checks] : counts.items()) {
        text += std::string(firstStage ? "\n" : ",\n") + "  " + json(stage).dump() + ": " +
                checks.dump();
        firstStage = false;
    }
    return text + (firstStage ? "" : "\n ") + "}\n}\n";
}
#endif

FunctionTables parseFunctionTables(const std::string& text, const std::string& file,
                                   TableCoverage coverage) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception& e) { throw Error(file + ": not JSON: " + e.what()); }
    if (!doc.contains("functions") || !doc["functions"].is_object())
        throw Error(file + ": expected an object \"functions\"");
    FunctionTables tables;
    for (const FunctionSpec& spec : functionSpecs()) {
        const std::string where = file + ": " + spec.name;
        if (!doc["functions"].contains(spec.name)) {
            if (coverage == TableCoverage::Some) continue;
            throw Error(where + ": missing (write the file again: raylab function-tables)");
        }
        const json& entry = doc["functions"][spec.name];
        if (!entry.is_object() || !entry.contains("cases") || !entry.contains("prelude") ||
            !entry.contains("helpers") || !entry["prelude"].is_string() ||
            !entry["helpers"].is_string())
            throw Error(where + ": expected {\"prelude\", \"helpers\", \"cases\"} (write the file "
                                "again: raylab function-tables)");
        const json& cases = entry["cases"];
        if (!cases.is_array() || cases.size() != spec.cases.size())
            throw Error(where + ": " + std::to_string(cases.is_array() ? cases.size() : 0) +
                        " cases, the check has " + std::to_string(spec.cases.size()) +
                        " (write the file again: raylab function-tables)");
        FunctionTable& t = tables[spec.name];
        t.prelude = entry["prelude"].get<std::string>();
        t.helpers = entry["helpers"].get<std::string>();
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const json& c = cases[i];
            const std::string at = where + "[" + std::to_string(i) + "]";
            if (!c.is_object() || !c.contains("case") || !c.contains("want") ||
                !c["want"].is_array() || c["want"].size() != 4)
                throw Error(at + ": expected {\"case\": label, \"want\": [4 numbers]}");
            if (c["case"] != spec.cases[i].label)
                throw Error(at + ": case \"" + c["case"].dump() + "\", the check's is \"" +
                            spec.cases[i].label +
                            "\" (write the file again: raylab function-tables)");
            // The inputs this build made must be the table's: a case built
            // differently (an argument order left to the compiler, a libm
            // one step apart) would be scored against another case's answer.
            if (!c.contains("in") || !c["in"].is_array() || c["in"].size() != 4)
                throw Error(at + ": expected \"in\": [4 vectors of 4 numbers]");
            for (std::size_t k = 0; k < 4; ++k)
                for (int j = 0; j < 4; ++j) {
                    const double mine = spec.cases[i].in[k][j];
                    const double theirs = numberFrom(c["in"][k].at(std::size_t(j)), at);
                    if (!(std::fabs(mine - theirs) <= 1e-9 * std::max(1.0, std::fabs(mine))) &&
                        !(std::isnan(mine) && std::isnan(theirs)))
                        throw Error(at + ": input a" + std::to_string(k) + "[" + std::to_string(j) +
                                    "] is " + std::to_string(mine) + " here, " +
                                    std::to_string(theirs) +
                                    " in the table: this build makes another case");
                }
            if (c.contains("either") && !c["either"].is_boolean())
                throw Error(at + ": \"either\" must be true or false");
            t.labels.push_back(spec.cases[i].label);
            t.either.push_back(c.value("either", false));
            t.wants.emplace_back(numberFrom(c["want"][0], at), numberFrom(c["want"][1], at),
                                 numberFrom(c["want"][2], at), numberFrom(c["want"][3], at));
        }
    }
    for (const auto& item : doc["functions"].items())
        if (!tables.count(item.key()))
            throw Error(file + ": " + item.key() +
                        ": no such function check (write the file again: raylab "
                        "function-tables)");
    return tables;
}

const FunctionTable& tableOf(const FunctionTables& tables, const std::string& name,
                             const std::string& file) {
    const auto it = tables.find(name);
    if (it == tables.end())
        throw Error(file + " has no table for " + name +
                    " (a bundle holds its released stages' checks only)");
    return it->second;
}

const FunctionTables& tablesAsData() {
    static const FunctionTables tables = parseFunctionTables(
        readTextFile(projectRoot() / kTablesAsData), kTablesAsData, TableCoverage::Some);
    return tables;
}

FunctionSpec withHarnessFrom(const FunctionTables& tables, const FunctionSpec& spec,
                             const std::string& file) {
    const FunctionTable& table = tableOf(tables, spec.name, file);
    FunctionSpec out = spec;
    out.prelude = table.prelude;
    out.helpers = table.helpers;
    for (std::size_t i = 0; i < out.cases.size() && i < table.either.size(); ++i)
        out.cases[i].hitOrMiss = table.either[i];
    return out;
}

}  // namespace raylab
