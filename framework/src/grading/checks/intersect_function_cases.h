#pragma once
// The function-check tables of the intersection routines:
// intersect_function_cases.cpp (functionSpecs() lists them with the rest).
#include "function_checks.h"

namespace raylab {

FunctionSpec sphereSpec();        // intersectSphere (stage 01)
FunctionSpec planeSpec();         // intersectPlane (stage 05)
FunctionSpec discSpec();          // intersectDisc
FunctionSpec triangleSpec();      // intersectTriangle
FunctionSpec torusNormalSpec();   // the torus's normal
FunctionSpec torusQuarticSpec();  // the quartic's coefficients (the open level writes them)

}  // namespace raylab
