#include "run/test_hooks.hpp"

#include <csignal>
#include <cstdlib>
#include <string>

namespace canopy::test_hooks {

namespace {

struct KillHook {
    long after_groups = -1;  // -1: no hook
    long after_chunks = -1;
    bool mid_group = false;
    int signal = SIGKILL;
};

const KillHook& hook() {
    static const KillHook h = [] {
        KillHook k;
        if (const char* n = std::getenv("CANOPY_TEST_KILL_AFTER_GROUPS"); n && *n) k.after_groups = std::strtol(n, nullptr, 10);
        if (const char* n = std::getenv("CANOPY_TEST_KILL_AFTER_CHUNKS"); n && *n) k.after_chunks = std::strtol(n, nullptr, 10);
        if (const char* mid = std::getenv("CANOPY_TEST_KILL_MID_GROUP")) k.mid_group = std::string(mid) == "1";
        if (const char* s = std::getenv("CANOPY_TEST_KILL_SIGNAL")) {
            const std::string name = s;
            k.signal = name == "TERM" ? SIGTERM : name == "INT" ? SIGINT : SIGKILL;
        }
        return k;
    }();
    return h;
}

}  // namespace

void case_images_written(size_t groups_recorded) {
    const KillHook& h = hook();
    if (h.after_groups >= 0 && h.mid_group && long(groups_recorded) == h.after_groups) std::raise(h.signal);
}

void group_recorded(size_t groups_recorded) {
    const KillHook& h = hook();
    if (h.after_groups >= 0 && !h.mid_group && long(groups_recorded) == h.after_groups) std::raise(h.signal);
}

void chunk_recorded(size_t chunks_recorded) {
    const KillHook& h = hook();
    if (h.after_chunks >= 0 && long(chunks_recorded) == h.after_chunks) std::raise(h.signal);
}

}  // namespace canopy::test_hooks
