// The reference's stall watch (reference/stall_watch.hpp): Embree cannot be interrupted inside a
// ray query, so when no pixel of a reference finishes for the stall limit, canopy ends the process
// with exit code 1 and names the pixels being traced. Run in a child process (fork), whose pixel
// never returns in time; a trace whose pixels finish is left alone.
#include "reference/stall_watch.hpp"
#include "reference/tiled_trace.hpp"

#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

using namespace canopy;

namespace {

// Runs `body` in a child process; its exit code (or -signal) and what it wrote to stderr.
std::pair<int, std::string> in_child(const std::function<void()>& body) {
    int pipe_fds[2];
    REQUIRE(pipe(pipe_fds) == 0);
    std::fflush(nullptr);
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        close(pipe_fds[0]);
        dup2(pipe_fds[1], STDERR_FILENO);
        body();
        std::_Exit(0);
    }
    close(pipe_fds[1]);
    std::string err;
    char buffer[512];
    for (ssize_t n; (n = read(pipe_fds[0], buffer, sizeof buffer)) > 0;) err.append(buffer, size_t(n));
    close(pipe_fds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status), err};
}

}  // namespace

TEST_CASE("reference: a pixel that never returns ends the process with exit code 1, naming the pixel") {
    const auto [code, err] = in_child([] {
        trace_tiles(8, 4, 2, nullptr, ShadowQuery::packet16, {}, [](int x, int y, EmbreeShadowTracer&) {
            if (x == 5 && y == 2) std::this_thread::sleep_for(std::chrono::seconds(30));
        }, 0.5);
    });
    CAPTURE(err);
    CHECK(code == 1);
    CHECK(err.find("stalled: no pixel finished") != std::string::npos);
    CHECK(err.find("(5, 2)") != std::string::npos);
    CHECK(err.find("run the same command again") != std::string::npos);
}

TEST_CASE("reference: slow pixels that keep finishing are not a stall") {
    const auto [code, err] = in_child([] {
        trace_tiles(4, 4, 2, nullptr, ShadowQuery::packet16, {}, [](int, int, EmbreeShadowTracer&) {
            std::this_thread::sleep_for(std::chrono::milliseconds(60));
        }, 0.5);
    });
    CAPTURE(err);
    CHECK(code == 0);
    CHECK(err.empty());
}

TEST_CASE("reference: the stall limit comes from CANOPY_REFERENCE_STALL_SECONDS, 300 s otherwise") {
    unsetenv("CANOPY_REFERENCE_STALL_SECONDS");
    CHECK(reference_stall_seconds() == 300.0);
    setenv("CANOPY_REFERENCE_STALL_SECONDS", "12.5", 1);
    CHECK(reference_stall_seconds() == 12.5);
    setenv("CANOPY_REFERENCE_STALL_SECONDS", "-3", 1);
    CHECK(reference_stall_seconds() == 300.0);
    setenv("CANOPY_REFERENCE_STALL_SECONDS", "soon", 1);
    CHECK(reference_stall_seconds() == 300.0);
    unsetenv("CANOPY_REFERENCE_STALL_SECONDS");
}
