#include "stage_catalog.h"

#include "error.h"
#include "json_reader.h"
#include "paths.h"
#include "render_settings.h"

#include <algorithm>
#include <fstream>
#include <map>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// What a stage may ask of the framework. The reference tracer, the debug
// views and `raylab demo`/`bench` read these instead of stage numbers.
const std::set<std::string> kKnownFeatures = {
    "shading",      // Blinn-Phong (else the flat colour of ray casting)
    "shadows",      // shadow rays
    "recursion",    // mirror, glass and metal rays on a stack
    "surface_at",   // the stage's GLSL has surfaceAt() (any object's normal)
    "textures",     // textures, sky box, glow
    "normal_maps",  //
    "color_modes",  // the seed's colour modes (Up/Down)
    "demo",         // the stage `raylab demo` and `raylab bench` run (of its track)
    // The fur track:
    "mesh",        // a lit, textured triangle mesh (rasterised)
    "shells",      // the fur as shells: the mesh drawn again and again, a layer further out
    "fins",        // fins at silhouette edges from a geometry shader ("fins" program)
    "fur_shader",  // strands from a geometry shader per triangle ("strands" program)
};

// The count checks a track's renderer can run (track_renderer.h).
const std::set<std::string> kKnownCountChecks = {
    "fin_count",  // fins the geometry shader emits = silhouette edges counted on the CPU
};

// Reads typed values out of one stage.json with "FILE: KEY: ..." errors.
// The stage file's value kinds on top of JsonReader's (json_reader.h).
struct StageReader : JsonReader {
    std::string text(const json& v, const std::string& key) const {
        std::string s = string(v, key);
        if (s.empty()) fail(key, "expected a non-empty string");
        return s;
    }
    int count(const json& v, const std::string& key) const {
        if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 1000000)
            fail(key, "expected a whole number from 0 to 1000000");
        return v.get<int>();
    }
    bool flag(const json& v, const std::string& key) const {
        if (!v.is_boolean()) fail(key, "expected true or false");
        return v.get<bool>();
    }
    std::vector<std::string> strings(const json& v, const std::string& key) const {
        if (!v.is_array()) fail(key, "expected a list of strings");
        std::vector<std::string> out;
        for (std::size_t i = 0; i < v.size(); ++i)
            out.push_back(text(v[i], key + "[" + std::to_string(i) + "]"));
        return out;
    }
    // Optional members: the default when absent.
    template <typename T, typename Read>
    T optional(const json& obj, const std::string& where, const char* key, T fallback,
               Read read) const {
        return obj.contains(key) ? read(obj[key], where + "." + key) : fallback;
    }

    StageProgram program(const json& v, const std::string& where = "program") const {
        allowOnly(v, where, {"vertex", "geometry", "fragment"});
        StageProgram p;
        p.vertex = text(member(v, where, "vertex"), where + ".vertex");
        if (v.contains("geometry")) p.geometry = text(v["geometry"], where + ".geometry");
        p.fragment = text(member(v, where, "fragment"), where + ".fragment");
        return p;
    }

    StageLimits limits(const json& v) const {
        if (!v.is_object()) fail("limits", "expected an object");
        allowOnly(v, "limits",
                  {"spheres", "materials", "lights", "planes", "discs", "triangles", "tori",
                   "mesh_triangles", "textures", "sky_box"});
        StageLimits l;
        auto c = [&](const char* key, int fallback) {
            return optional(v, "limits", key, fallback,
                            [&](const json& x, const std::string& k) { return count(x, k); });
        };
        l.spheres = c("spheres", l.spheres);
        l.materials = c("materials", l.materials);
        l.lights = c("lights", l.lights);
        l.planes = c("planes", l.planes);
        l.discs = c("discs", l.discs);
        l.triangles = c("triangles", l.triangles);
        l.tori = c("tori", l.tori);
        l.meshTriangles = c("mesh_triangles", l.meshTriangles);
        l.textures = c("textures", l.textures);
        l.skyBox = optional(v, "limits", "sky_box", false,
                            [&](const json& x, const std::string& k) { return flag(x, k); });
        return l;
    }

    CheckView view(const json& v, const std::string& where) const {
        allowOnly(v, where,
                  {"name", "why", "hint", "camera", "time", "shadows", "max_depth", "glow",
                   "normal_maps", "color_mode", "scene", "shells", "fins", "technique"});
        CheckView c;
        c.name = text(member(v, where, "name"), where + ".name");
        c.why = text(member(v, where, "why"), where + ".why");
        if (v.contains("hint")) c.hint = text(v["hint"], where + ".hint");
        if (v.contains("camera")) {
            const json& cam = v["camera"];
            const std::string at = where + ".camera";
            allowOnly(cam, at, {"position", "yaw", "pitch"});
            const json& p = member(cam, at, "position");
            if (!p.is_array() || p.size() != 3) fail(at + ".position", "expected [x, y, z]");
            CameraPose pose;
            for (int i = 0; i < 3; ++i)
                pose.position[i] = number(p[std::size_t(i)], at + ".position");
            pose.yawDeg = number(member(cam, at, "yaw"), at + ".yaw");
            pose.pitchDeg = number(member(cam, at, "pitch"), at + ".pitch");
            c.pose = pose;
        }
        auto b = [&](const char* key, bool fallback) {
            return optional(v, where, key, fallback,
                            [&](const json& x, const std::string& k) { return flag(x, k); });
        };
        c.time = optional(v, where, "time", 0.0f,
                          [&](const json& x, const std::string& k) { return number(x, k); });
        c.shadows = b("shadows", true);
        c.glow = b("glow", true);
        c.normalMaps = b("normal_maps", true);
        c.maxDepth = optional(v, where, "max_depth", RenderSettings::kMaxDepth,
                              [&](const json& x, const std::string& k) {
                                  int d = count(x, k);
                                  if (d < 1 || d > RenderSettings::kMaxDepth)
                                      fail(k, "expected a depth from 1 to " +
                                                  std::to_string(RenderSettings::kMaxDepth));
                                  return d;
                              });
        if (v.contains("color_mode")) {
            const std::string mode = text(v["color_mode"], where + ".color_mode");
            auto it = std::find(std::begin(kColorModes), std::end(kColorModes), mode);
            if (it == std::end(kColorModes))
                fail(where + ".color_mode", "expected RGB, BRB, BRR, RBB or GGR");
            c.colorMode = int(it - std::begin(kColorModes));
        }
        if (v.contains("scene")) c.scene = text(v["scene"], where + ".scene");
        c.fins = b("fins", true);
        c.shells = optional(v, where, "shells", 0, [&](const json& x, const std::string& k) {
            int n = count(x, k);
            if (n < 1 || n > RenderSettings::kMaxShells)
                fail(k, "expected a shell count from 1 to " +
                            std::to_string(RenderSettings::kMaxShells));
            return n;
        });
        if (v.contains("technique")) {
            const std::string t = text(v["technique"], where + ".technique");
            auto it = std::find(std::begin(kFurTechniques), std::end(kFurTechniques), t);
            if (it == std::end(kFurTechniques))
                fail(where + ".technique", "expected shells_and_fins or fur_shader");
            c.furTechnique = int(it - std::begin(kFurTechniques));
        }
        return c;
    }
};

// Kahn's order: a stage comes after the one it builds on; ties by id, so a
// track reads in the order of its ids. Tracks follow their first stage's id.
std::vector<StageInfo> inBuildOrder(std::vector<StageInfo> stages) {
    std::sort(stages.begin(), stages.end(),
              [](const StageInfo& a, const StageInfo& b) { return a.id < b.id; });
    std::map<std::string, const StageInfo*> byId;
    for (const StageInfo& s : stages) byId[s.id] = &s;
    for (const StageInfo& s : stages)
        if (!s.buildsOn.empty() && !byId.count(s.buildsOn))
            throw Error(displayPath(s.folder() / "stage.json") + ": builds_on: no stage '" +
                        s.buildsOn + "' (no solution/" + s.buildsOn + "/stage.json)");
    std::vector<StageInfo> ordered;
    std::set<std::string> placed;
    std::vector<std::string> trackOrder;
    while (ordered.size() < stages.size()) {
        const StageInfo* next = nullptr;
        for (const StageInfo& s : stages)
            if (!placed.count(s.id) && (s.buildsOn.empty() || placed.count(s.buildsOn))) {
                next = &s;
                break;
            }
        if (!next) {
            for (const StageInfo& s : stages)
                if (!placed.count(s.id))
                    throw Error(displayPath(s.folder() / "stage.json") + ": builds_on: '" +
                                s.buildsOn + "' leads in a circle");
        }
        placed.insert(next->id);
        ordered.push_back(*next);
        if (std::find(trackOrder.begin(), trackOrder.end(), next->track) == trackOrder.end())
            trackOrder.push_back(next->track);
    }
    std::stable_sort(ordered.begin(), ordered.end(), [&](const StageInfo& a, const StageInfo& b) {
        return std::find(trackOrder.begin(), trackOrder.end(), a.track) <
               std::find(trackOrder.begin(), trackOrder.end(), b.track);
    });
    return ordered;
}

std::vector<StageInfo> readStages() {
    const fs::path solution = projectRoot() / "solution";
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(solution, ec))
        if (e.is_directory() && fs::is_regular_file(e.path() / "stage.json"))
            files.push_back(e.path() / "stage.json");
    std::vector<StageInfo> stages;
    for (const fs::path& f : files) stages.push_back(readStageFile(f));
    return inBuildOrder(std::move(stages));
}

std::string stageList() {
    std::string list;
    for (const StageInfo& s : allStages()) list += (list.empty() ? "" : ", ") + s.id;
    return list;
}

}  // namespace

StageInfo readStageFile(const fs::path& file) {
    const std::string shown = displayPath(file);
    StageReader r{{shown}};
    const json doc = parseJsonFile(file, shown);
    if (!doc.is_object()) r.fail("(top level)", "expected an object");
    r.allowOnly(doc, "",
                {"id", "title", "track", "builds_on", "scene", "program", "programs", "limits",
                 "features", "function_checks", "count_checks", "mistakes", "check_views",
                 "defines", "hints", "grading", "technique"});
    StageInfo s;
    s.id = r.text(r.member(doc, "stage", "id"), "id");
    if (s.id != file.parent_path().filename().string())
        r.fail("id", "'" + s.id + "' is not the folder's name '" +
                         file.parent_path().filename().string() + "'");
    s.title = r.text(r.member(doc, "stage", "title"), "title");
    s.track = r.text(r.member(doc, "stage", "track"), "track");
    const json& on = r.member(doc, "stage", "builds_on");
    if (!on.is_null()) s.buildsOn = r.text(on, "builds_on");
    if (s.buildsOn == s.id) r.fail("builds_on", "a stage cannot build on itself");
    s.scene = r.text(r.member(doc, "stage", "scene"), "scene");
    s.program = r.program(r.member(doc, "stage", "program"));
    if (doc.contains("programs")) {
        const json& more = doc["programs"];
        if (!more.is_object()) r.fail("programs", "expected an object of named programs");
        for (auto it = more.begin(); it != more.end(); ++it)
            s.programs[it.key()] = r.program(it.value(), "programs." + it.key());
    }
    s.limits = r.limits(r.member(doc, "stage", "limits"));
    const std::vector<std::string> features =
        r.strings(r.member(doc, "stage", "features"), "features");
    for (std::size_t i = 0; i < features.size(); ++i) {
        if (!kKnownFeatures.count(features[i])) {
            std::string known;
            for (const std::string& k : kKnownFeatures) known += (known.empty() ? "" : ", ") + k;
            r.fail("features[" + std::to_string(i) + "]",
                   "unknown feature '" + features[i] + "' (known: " + known + ")");
        }
        s.features.insert(features[i]);
    }
    s.functionChecks = r.strings(r.member(doc, "stage", "function_checks"), "function_checks");
    if (doc.contains("count_checks")) {
        s.countChecks = r.strings(doc["count_checks"], "count_checks");
        for (std::size_t i = 0; i < s.countChecks.size(); ++i)
            if (!kKnownCountChecks.count(s.countChecks[i]))
                r.fail("count_checks[" + std::to_string(i) + "]",
                       "unknown count check '" + s.countChecks[i] + "' (known: fin_count)");
    }
    s.mistakes = r.text(r.member(doc, "stage", "mistakes"), "mistakes");
    if (s.mistakes.is_absolute() || s.mistakes.lexically_normal().string().rfind("..", 0) == 0)
        r.fail("mistakes", "expected a folder inside the project, relative to its root");
    // The fur technique the stage's pictures show unless told otherwise: its
    // own work (f4: the fur shader), in the window, `render` and check views.
    if (doc.contains("technique")) {
        const std::string t = r.text(doc["technique"], "technique");
        auto it = std::find(std::begin(kFurTechniques), std::end(kFurTechniques), t);
        if (it == std::end(kFurTechniques))
            r.fail("technique", "expected shells_and_fins or fur_shader");
        s.furTechnique = int(it - std::begin(kFurTechniques));
    }
    const json& views = r.member(doc, "stage", "check_views");
    if (!views.is_array() || views.empty())
        r.fail("check_views", "expected a non-empty list of views");
    for (std::size_t i = 0; i < views.size(); ++i) {
        CheckView v = r.view(views[i], "check_views[" + std::to_string(i) + "]");
        if (!views[i].contains("technique")) v.furTechnique = s.furTechnique;
        for (const CheckView& earlier : s.checkViews)
            if (earlier.name == v.name)
                r.fail("check_views[" + std::to_string(i) + "].name",
                       "'" + v.name + "' is used twice");
        s.checkViews.push_back(v);
    }
    if (doc.contains("defines")) s.extraDefines = r.strings(doc["defines"], "defines");
    if (doc.contains("hints")) {
        const json& h = doc["hints"];
        r.allowOnly(h, "hints", {"darker", "brighter"});
        if (h.contains("darker")) s.hintDarker = r.text(h["darker"], "hints.darker");
        if (h.contains("brighter")) s.hintBrighter = r.text(h["brighter"], "hints.brighter");
    }
    if (doc.contains("grading")) s.grading = readGrading(r, doc["grading"], "grading", s.grading);
    validateGrading(s.grading, s, shown + ": grading");
    return s;
}

StageGrading readGrading(const JsonReader& r, const json& v, const std::string& where,
                         StageGrading grading) {
    if (!v.is_object()) r.fail(where, "expected an object");
    r.allowOnly(v, where, {"views", "weights", "seeded_views"});
    if (v.contains("seeded_views")) {
        const json& n = v["seeded_views"];
        if (!n.is_number_integer() || n.get<int>() < 0 || n.get<int>() > kSeededViewsPerStage)
            r.fail(where + ".seeded_views", "expected a whole number of views from 0 to " +
                                                std::to_string(kSeededViewsPerStage));
        grading.seededViews = n.get<int>();
    }
    if (v.contains("views")) {
        const json& views = v["views"];
        if (!views.is_number() || views.get<double>() < 0.0 || views.get<double>() > 100.0)
            r.fail(where + ".views", "expected the image checks' points, from 0 to 100");
        grading.viewPoints = views.get<double>();
    }
    if (v.contains("weights")) {
        const json& w = v["weights"];
        if (!w.is_object())
            r.fail(where + ".weights", "expected an object of check names and weights");
        for (auto it = w.begin(); it != w.end(); ++it) {
            if (it.key() == "comment") continue;
            if (!it.value().is_number() || it.value().get<double>() < 0.0)
                r.fail(where + ".weights." + it.key(), "expected a weight of 0 or more");
            grading.weights[it.key()] = it.value().get<double>();
        }
    }
    return grading;
}

std::vector<std::string> StageInfo::defines() const {
    auto size = [](const char* name, int limit) {
        return std::string(name) + " " + std::to_string(std::max(1, limit));
    };
    std::vector<std::string> all = {
        size("MAX_SPHERES", limits.spheres), size("MAX_MATERIALS", limits.materials),
        size("MAX_LIGHTS", limits.lights),   size("MAX_PLANES", limits.planes),
        size("MAX_DISCS", limits.discs),     size("MAX_TRIANGLES", limits.triangles),
        size("MAX_TORI", limits.tori)};
    all.insert(all.end(), extraDefines.begin(), extraDefines.end());
    return all;
}

fs::path StageInfo::folder() const { return projectRoot() / "solution" / id; }

fs::path StageInfo::sceneFileOf(const CheckView& view) const {
    return projectRoot() / "assets" / "scenes" / (view.scene.empty() ? scene : view.scene);
}

const std::vector<StageInfo>& allStages() {
    static const std::vector<StageInfo> stages = readStages();
    return stages;
}

const StageInfo& findStage(const std::string& idOrNumber) {
    const bool digits = !idOrNumber.empty() && idOrNumber.size() <= 3 &&
                        idOrNumber.find_first_not_of("0123456789") == std::string::npos;
    for (const StageInfo& s : allStages()) {
        const std::string n = s.number();
        const bool numberMatches = digits && !n.empty() && n.size() <= 3 &&
                                   n.find_first_not_of("0123456789") == std::string::npos &&
                                   std::stoi(idOrNumber) == std::stoi(n);
        if (idOrNumber == s.id || idOrNumber == n || numberMatches) return s;
    }
    throw Error("unknown stage '" + idOrNumber + "' (stages: " + stageList() + ")");
}

const StageInfo& demoStage(const std::string& track) {
    const StageInfo* demo = nullptr;
    for (const StageInfo& s : allStages())
        if (s.has("demo") && s.track == track) demo = &s;
    if (!demo)
        throw Error("no stage of track '" + track +
                    "' has the \"demo\" feature (solution/*/stage.json)");
    return *demo;
}

std::vector<std::pair<std::string, const StageProgram*>> StageInfo::allPrograms() const {
    std::vector<std::pair<std::string, const StageProgram*>> all = {{"program", &program}};
    for (const auto& [name, p] : programs) all.emplace_back("programs." + name, &p);
    return all;
}

const StageProgram& namedProgram(const StageInfo& stage, const char* name, const char* feature) {
    auto it = stage.programs.find(name);
    if (it == stage.programs.end())
        throw Error(displayPath(stage.folder() / "stage.json") + ": programs." + name +
                    ": the feature \"" + feature + "\" needs this program");
    return it->second;
}

}  // namespace raylab
