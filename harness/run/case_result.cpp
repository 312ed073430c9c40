#include "run/case_result.hpp"

namespace canopy {

bool same_reference(const ReferenceRecord& r, const std::string& scene, const Resolution& resolution) {
    return r.scene == scene && r.resolution.width == resolution.width && r.resolution.height == resolution.height;
}

const ReferenceRecord* reference_of(const RunRecord& run, const CaseResult& c) {
    for (const ReferenceRecord& r : run.references)
        if (same_reference(r, c.scene, c.resolution)) return &r;
    return nullptr;
}

const std::vector<std::string>& degenerate_reasons(const RunRecord& run, const CaseResult& c) {
    static const std::vector<std::string> none;
    const ReferenceRecord* r = reference_of(run, c);
    return r ? r->degenerate : none;
}

}  // namespace canopy
