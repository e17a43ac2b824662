#pragma once
// The fin count check's verdict: the fins a fin shader emitted for a mesh
// and a camera against the silhouette edges counted in double precision.
// The count itself is silhouette.h's (the reference, which a build without
// references reads as data: count_tables.h); the verdict is shared.
#include <cstddef>
#include <string>

namespace raylab {

struct SilhouetteCount {
    long certain = 0;    // edges that are silhouettes beyond doubt
    long uncertain = 0;  // edges too close to edge-on to call
};

// A correct fin shader emits between `certain` and `certain + uncertain` fins.
struct FinCountVerdict {
    bool passed = false;
    std::string detail;  // "the geometry shader emitted 12 fins for 96 edges; ..."
};

// The verdict on EMITTED fins (native: a query of the real geometry shader;
// the page: its emulation's transform feedback) for a mesh of EDGES edges,
// in the report's words.
FinCountVerdict judgeFinCount(long emitted, std::size_t edges, const SilhouetteCount& cpu);

}  // namespace raylab
