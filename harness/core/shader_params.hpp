// What a technique hands its shaders besides resources: its parameter struct (declared once with
// CANOPY_PARAM_BLOCK, harness/shaders/param_block.h), uploaded as `frame.technique` at the end of
// the frame uniform block, plus an optional table of up to 128 vec2 sample offsets.
#pragma once

#include "core/param_block.hpp"

#include <array>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

namespace canopy {

struct ShaderParams {
    std::array<std::byte, kMaxParamBlockBytes> block{};  // the struct's bytes (std140 = C++ layout)
    std::vector<ParamBlockMember> layout;                 // its members; empty: no block
    std::vector<std::array<float, 2>> offsets;  // e.g. a Poisson disk; size() <= kMaxOffsets
    static constexpr size_t kMaxOffsets = 128;

    template <class Block>
    void set_block(const Block& values) {
        static_assert(sizeof(Block) <= kMaxParamBlockBytes && std::is_trivially_copyable_v<Block>);
        block.fill(std::byte{0});
        std::memcpy(block.data(), &values, sizeof(Block));
        layout = Block::layout();
    }
    // The block as `Block` (tests read what a plan hands its shaders).
    template <class Block>
    Block get_block() const {
        static_assert(sizeof(Block) <= kMaxParamBlockBytes && std::is_trivially_copyable_v<Block>);
        Block values;
        std::memcpy(&values, block.data(), sizeof(Block));
        return values;
    }
};

}  // namespace canopy
