// The ConfigError a piece of code throws, for tests of bad input: they check its file, line,
// message and hint.
#pragma once

#include "core/error.hpp"

#include <optional>

namespace canopy::test {

// The ConfigError `action()` throws, or nothing when it throws none (other exceptions pass).
template <typename Action>
std::optional<ConfigError> config_error_of(Action&& action) {
    try {
        action();
    } catch (const ConfigError& error) {
        return error;
    }
    return std::nullopt;
}

}  // namespace canopy::test
