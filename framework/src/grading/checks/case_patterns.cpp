#include "case_patterns.h"

namespace raylab {

CasePick labelStarts(std::string prefix) {
    return [prefix = std::move(prefix)](const CaseVerdict& v) {
        return v.input->label.rfind(prefix, 0) == 0;
    };
}

CasePick labelHas(std::string text) {
    return [text = std::move(text)](const CaseVerdict& v) {
        return v.input->label.find(text) != std::string::npos;
    };
}

CasePick either(CasePick a, CasePick b) {
    return [a = std::move(a), b = std::move(b)](const CaseVerdict& v) { return a(v) || b(v); };
}

bool anyFailed(const CaseVerdicts& v, const CasePick& pick) {
    for (const CaseVerdict& c : v)
        if (c.failed && pick(c)) return true;
    return false;
}

bool noneFailed(const CaseVerdicts& v, const CasePick& pick) { return !anyFailed(v, pick); }

bool onlyFailed(const CaseVerdicts& v, const CasePick& pick) {
    for (const CaseVerdict& c : v)
        if (c.failed && !pick(c)) return false;
    return true;
}

}  // namespace raylab
