// Techniques register themselves by name at static-initialisation time; the harness looks them
// up from configs and `canopy list`. Registration is separate from running.
#pragma once

#include "core/technique.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace canopy {

class TechniqueRegistry {
public:
    static TechniqueRegistry& instance();

    void add(std::unique_ptr<Technique> technique);  // throws std::logic_error on a duplicate name
    const Technique* find(const std::string& name) const;  // nullptr when unknown
    std::vector<const Technique*> all() const;             // sorted by name
    std::vector<std::string> names() const;

private:
    std::vector<std::unique_ptr<Technique>> techniques_;
};

// In a technique's .cpp:  static canopy::RegisterTechnique<PcfShadows> registered;
template <typename T>
struct RegisterTechnique {
    RegisterTechnique() { TechniqueRegistry::instance().add(std::make_unique<T>()); }
};

}  // namespace canopy
