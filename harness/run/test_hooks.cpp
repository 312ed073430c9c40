#include "run/test_hooks.hpp"

#include <csignal>
#include <cstdlib>
#include <string>

namespace canopy::test_hooks {

namespace {

struct KillHook {
    long after_cases = -1;  // -1: no hook
    bool mid_case = false;
    int signal = SIGKILL;
};

const KillHook& hook() {
    static const KillHook h = [] {
        KillHook k;
        if (const char* n = std::getenv("CANOPY_TEST_KILL_AFTER_CASES"); n && *n) k.after_cases = std::strtol(n, nullptr, 10);
        if (const char* mid = std::getenv("CANOPY_TEST_KILL_MID_CASE")) k.mid_case = std::string(mid) == "1";
        if (const char* s = std::getenv("CANOPY_TEST_KILL_SIGNAL")) {
            const std::string name = s;
            k.signal = name == "TERM" ? SIGTERM : name == "INT" ? SIGINT : SIGKILL;
        }
        return k;
    }();
    return h;
}

}  // namespace

void case_images_written(size_t measured) {
    const KillHook& h = hook();
    if (h.after_cases >= 0 && h.mid_case && long(measured) == h.after_cases + 1) std::raise(h.signal);
}

void case_recorded(size_t measured) {
    const KillHook& h = hook();
    if (h.after_cases >= 0 && !h.mid_case && long(measured) == h.after_cases) std::raise(h.signal);
}

}  // namespace canopy::test_hooks
