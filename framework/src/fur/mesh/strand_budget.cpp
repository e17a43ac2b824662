#include "strand_budget.h"

#include "error.h"

#include <algorithm>

namespace raylab {

StrandBudget strandBudget(int maxOutputVertices, int maxTotalComponents, int segments) {
    StrandBudget b{maxOutputVertices, maxTotalComponents, segments, 0};
    const int perStrand = segments + 1;
    const int byVertices = maxOutputVertices / perStrand;
    const int byComponents = maxTotalComponents / (perStrand * kStrandVertexComponents);
    b.strandsPerTriangle = std::min({kStrandsWanted, byVertices, byComponents});
    if (b.strandsPerTriangle < 1)
        throw Error("the fur shader cannot emit one strand of " + std::to_string(segments) +
                    " segments: this driver allows " + std::to_string(maxOutputVertices) +
                    " vertices and " + std::to_string(maxTotalComponents) +
                    " components per geometry-shader invocation");
    return b;
}

std::vector<std::string> StrandBudget::defines() const {
    return {"STRAND_SEGMENTS " + std::to_string(segments),
            "STRANDS_PER_TRIANGLE " + std::to_string(strandsPerTriangle),
            "STRAND_MAX_VERTICES " + std::to_string(maxVertices())};
}

std::string StrandBudget::describe() const {
    return std::to_string(strandsPerTriangle) + " strands x " + std::to_string(segments + 1) +
           " vertices x " + std::to_string(kStrandVertexComponents) +
           " components = " + std::to_string(maxVertices() * kStrandVertexComponents) + " of " +
           std::to_string(maxTotalComponents) + " (max " + std::to_string(maxOutputVertices) +
           " vertices)";
}

}  // namespace raylab
