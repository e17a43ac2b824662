#include "fin_count.h"

namespace raylab {

FinCountVerdict judgeFinCount(long emitted, std::size_t edges, const SilhouetteCount& cpu) {
    FinCountVerdict v;
    v.passed = emitted >= cpu.certain && emitted <= cpu.certain + cpu.uncertain;
    v.detail = "the geometry shader emitted " + std::to_string(emitted) + " fins for " +
               std::to_string(edges) + " edges; " + std::to_string(cpu.certain) +
               " edges are silhouettes" +
               (cpu.uncertain ? " (and " + std::to_string(cpu.uncertain) +
                                    " edge-on ones may count either way)"
                              : "");
    return v;
}

}  // namespace raylab
