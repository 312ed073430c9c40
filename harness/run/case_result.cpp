#include "run/case_result.hpp"

namespace canopy {

const ReferenceRecord* reference_of(const RunRecord& run, const CaseResult& c) {
    for (const ReferenceRecord& r : run.references)
        if (r.scene == c.scene && r.resolution.width == c.resolution.width && r.resolution.height == c.resolution.height)
            return &r;
    return nullptr;
}

const std::vector<std::string>& degenerate_reasons(const RunRecord& run, const CaseResult& c) {
    static const std::vector<std::string> none;
    const ReferenceRecord* r = reference_of(run, c);
    return r ? r->degenerate : none;
}

}  // namespace canopy
