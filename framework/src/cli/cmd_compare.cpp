// `raylab compare A.png B.png`: the graders' comparison of two pictures, as a
// command (for instructors checking a reference, and for the web build's
// tests, which compare the browser's picture with the native one).
#include "command.h"
#include "error.h"
#include "image_compare.h"

#include <cstdio>

namespace raylab {

namespace {

int cmdCompare(const std::string& a, const std::string& b, const std::string& heatMap) {
    const Image mine = loadPng(a);
    const Image expected = loadPng(b);
    if (mine.width != expected.width || mine.height != expected.height)
        throw Error(a + " is " + std::to_string(mine.width) + "x" + std::to_string(mine.height) +
                    " but " + b + " is " + std::to_string(expected.width) + "x" +
                    std::to_string(expected.height));
    const CompareTolerance tolerance;
    const ImageDiff diff = compareImages(mine, expected, tolerance.channel);
    const bool agree = imagesAgree(diff, tolerance);
    if (!heatMap.empty()) writePngAtomic(diffHeatMap(mine, expected), heatMap);
    std::printf("%s: %s (%s; the graders allow %.2g%% beyond %d/255)\n", a.c_str(),
                agree ? "agrees" : "DIFFERS", describe(diff).c_str(), tolerance.maxBadShare * 100.0,
                tolerance.channel);
    return agree ? 0 : 1;
}

}  // namespace

Command compareCommand() {
    return {
        "compare",
        "compare two PNG pictures with the graders' tolerance (exit 0: they agree, 1: they "
        "differ)",
        [](CLI::App& cmd) {
            auto files = std::make_shared<std::vector<std::string>>();
            auto heat = std::make_shared<std::string>();
            cmd.add_option("pictures", *files, "MINE.png EXPECTED.png")->required()->expected(2);
            cmd.add_option("--heat-map", *heat, "also write the difference heat map here (PNG)");
            return std::function<int()>(
                [=] { return cmdCompare((*files)[0], (*files)[1], *heat); });
        }};
}

}  // namespace raylab
