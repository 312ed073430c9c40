// The C++ side of typed parameter blocks (harness/shaders/param_block.h): what a block's
// generated code calls to read a ParamSet into the struct, and the block's layout as data, so
// tests can check that every declared parameter reaches the plan or the shader.
#pragma once

#include "core/param.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

namespace canopy {

// Largest parameter struct a technique may upload (the std140 frame block reserves this much).
inline constexpr size_t kMaxParamBlockBytes = 64;

// One member of a technique's shader parameter struct.
struct ParamBlockMember {
    enum class Kind { parameter, derived };  // copied from the declared parameter, or computed by plan()
    std::string name;
    uint32_t offset = 0;  // bytes from the struct's start (std140 = C++: 4-byte scalars, packed)
    Kind kind = Kind::parameter;
};

namespace param_block {

// Readers called by CANOPY_PARAM_BLOCK's generated from(): the spec's default and range come
// along with the name (the same arguments as ParamSpec's factories) and are ignored, except a
// choice's list, whose index the shader gets.
inline int32_t read_integer(const ParamSet& params, const char* name, long long, long long, long long) {
    return int32_t(params.integer(name));
}
inline float read_real(const ParamSet& params, const char* name, double, double, double) {
    return float(params.real(name));
}
inline uint32_t read_boolean(const ParamSet& params, const char* name, bool) { return params.boolean(name) ? 1u : 0u; }
inline int32_t read_choice(const ParamSet& params, const char* name, std::string_view,
                           std::initializer_list<std::string_view> choices) {
    const std::string& value = params.choice(name);
    const auto found = std::find(choices.begin(), choices.end(), value);
    if (found == choices.end()) throw std::logic_error("parameter '" + std::string(name) + "' holds an undeclared choice");
    return int32_t(found - choices.begin());
}

}  // namespace param_block
}  // namespace canopy
