// Typed parameter blocks: a technique writes each parameter once, in a list macro in a header
// that compiles as GLSL and as C++, and gets from it the GLSL struct its shaders read
// (frame.technique.<name>), the same C++ struct with std140-compatible layout, the ParamSpecs
// (name, type, default, range, doc) and the copy from a ParamSet into the struct.
//
//   #define PCF_PARAMS(SHADER, PLAN, DERIVED)     (one entry per line, each ending in a backslash)
//       PLAN(integer, resolution, (1024, 16, 8192), "shadow-map width and height in texels")
//       SHADER(integer, kernel, (3, 1, 11), "kernel width k: k*k depth tests per pixel")
//       SHADER(choice, pattern, ("grid", {"grid", "poisson"}), "sample layout")
//       DERIVED(real, reach, "farthest tap from the centre in texels")
//   CANOPY_BEGIN_NAMESPACE
//   CANOPY_PARAM_BLOCK(PcfParams, PCF_PARAMS)
//   CANOPY_END_NAMESPACE
//
// SHADER(type, name, (spec arguments), doc): a parameter the shaders read; a struct member that
//   from() fills. PLAN(...): a parameter only plan() reads (map size, format, passes); no member.
// DERIVED(type, name, doc): a member plan() computes from parameters; no parameter.
// type is integer (int), real (float), boolean (bool; uint32_t in C++) or choice (int: the
// index of the value in the choice list). The spec arguments are ParamSpec::<type>'s after the
// name: (default, min, max), (default) or (default, {choices}). Parameters are declared in list
// order; tests/test_param_coverage.cpp checks that each reaches the shader struct or the plan.
// A shader names its technique's struct with `#define TECHNIQUE_PARAMS PcfParams` before
// including frame_uniforms.glsl (the header does it for GLSL).
#ifndef CANOPY_PARAM_BLOCK_H
#define CANOPY_PARAM_BLOCK_H

#include "shared_math.h"

#ifdef __cplusplus
#include "core/param_block.hpp"

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#define CANOPY_PARAM_TYPE_integer int32_t
#define CANOPY_PARAM_TYPE_real float
#define CANOPY_PARAM_TYPE_boolean uint32_t
#define CANOPY_PARAM_TYPE_choice int32_t
#define CANOPY_PARAM_UNPAREN(...) __VA_ARGS__
#define CANOPY_PARAM_IGNORE(...)
#define CANOPY_PARAM_MEMBER(type, name, args, doc) CANOPY_PARAM_TYPE_##type name{};
#define CANOPY_PARAM_DERIVED_MEMBER(type, name, doc) CANOPY_PARAM_TYPE_##type name{};
#define CANOPY_PARAM_SPEC(type, name, args, doc) \
    specs.push_back(::canopy::ParamSpec::type(#name, CANOPY_PARAM_UNPAREN args, doc));
#define CANOPY_PARAM_COPY(type, name, args, doc) \
    block.name = ::canopy::param_block::read_##type(params, #name, CANOPY_PARAM_UNPAREN args);
#define CANOPY_PARAM_LAYOUT(type, name, args, doc) \
    members.push_back({#name, uint32_t(offsetof(Self, name)), ::canopy::ParamBlockMember::Kind::parameter});
#define CANOPY_PARAM_DERIVED_LAYOUT(type, name, doc) \
    members.push_back({#name, uint32_t(offsetof(Self, name)), ::canopy::ParamBlockMember::Kind::derived});
#define CANOPY_PARAM_COUNT(...) +1
#define CANOPY_PARAM_CHECK_SIZE(type, name, ...) \
    static_assert(sizeof(CANOPY_PARAM_TYPE_##type) == 4, "std140 packs 4-byte scalars only");

// The struct with its members in list order; specs() in list order; from() copies every SHADER
// parameter (DERIVED members stay 0 for plan() to set); layout() names each member's offset.
#define CANOPY_PARAM_BLOCK(Block, LIST)                                                          \
    struct Block {                                                                               \
        LIST(CANOPY_PARAM_MEMBER, CANOPY_PARAM_IGNORE, CANOPY_PARAM_DERIVED_MEMBER)              \
        static std::vector<::canopy::ParamSpec> specs() {                                        \
            std::vector<::canopy::ParamSpec> specs;                                              \
            LIST(CANOPY_PARAM_SPEC, CANOPY_PARAM_SPEC, CANOPY_PARAM_IGNORE)                      \
            return specs;                                                                        \
        }                                                                                        \
        static Block from(const ::canopy::ParamSet& params) {                                    \
            Block block;                                                                         \
            (void)params; /* a block of DERIVED members only reads none */                      \
            LIST(CANOPY_PARAM_COPY, CANOPY_PARAM_IGNORE, CANOPY_PARAM_IGNORE)                    \
            return block;                                                                        \
        }                                                                                        \
        static std::vector<::canopy::ParamBlockMember> layout();                                 \
    };                                                                                           \
    inline std::vector<::canopy::ParamBlockMember> Block::layout() {                             \
        using Self = Block;                                                                      \
        std::vector<::canopy::ParamBlockMember> members;                                         \
        LIST(CANOPY_PARAM_LAYOUT, CANOPY_PARAM_IGNORE, CANOPY_PARAM_DERIVED_LAYOUT)              \
        return members;                                                                          \
    }                                                                                            \
    LIST(CANOPY_PARAM_CHECK_SIZE, CANOPY_PARAM_IGNORE, CANOPY_PARAM_CHECK_SIZE)                  \
    /* std140 lays 4-byte scalars out back to back from offset 0, as C++ does here */            \
    static_assert(std::is_standard_layout_v<Block> && std::is_trivially_copyable_v<Block>);      \
    static_assert(sizeof(Block) ==                                                               \
                      4 * (0 LIST(CANOPY_PARAM_COUNT, CANOPY_PARAM_IGNORE, CANOPY_PARAM_COUNT)), \
                  "members must be packed 4-byte scalars, as std140 lays them out");             \
    static_assert(sizeof(Block) <= ::canopy::kMaxParamBlockBytes, "parameter block too large");

#else  // GLSL: the struct alone

#define CANOPY_PARAM_GLSL_integer int
#define CANOPY_PARAM_GLSL_real float
#define CANOPY_PARAM_GLSL_boolean bool
#define CANOPY_PARAM_GLSL_choice int
#define CANOPY_PARAM_GLSL_MEMBER(type, name, args, doc) CANOPY_PARAM_GLSL_##type name;
#define CANOPY_PARAM_GLSL_DERIVED(type, name, doc) CANOPY_PARAM_GLSL_##type name;
#define CANOPY_PARAM_GLSL_NONE(type, name, args, doc)
#define CANOPY_PARAM_BLOCK(Block, LIST) \
    struct Block { LIST(CANOPY_PARAM_GLSL_MEMBER, CANOPY_PARAM_GLSL_NONE, CANOPY_PARAM_GLSL_DERIVED) };

#endif

#endif
