// A source changed after the binary was linked is found and named; other files are not sources.
#include "run/binary_freshness.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>

#include <chrono>

using namespace canopy;

TEST_CASE("a source file newer than the binary is named, the newest of several; other files are ignored") {
    test::TempFolder checkout;
    const auto a = checkout.write("harness/run/a.cpp", "int a;");
    const auto b = checkout.write("techniques/grass/shaders/b.glsl", "// b");
    const auto notes = checkout.write("results/grass/README.md", "notes");
    const auto data = checkout.write("techniques/grass/tests/data.json", "{}");
    const auto family_test = checkout.write("techniques/grass/tests/test_x.cpp", "// a family's test");
    const auto lists = checkout.write("CMakeLists.txt", "project(x)");
    const auto built = std::filesystem::file_time_type::clock::now();
    const auto at = [&](const std::filesystem::path& file, int seconds) {
        std::filesystem::last_write_time(file, built + std::chrono::seconds(seconds));
    };
    for (const auto& file : {a, b, notes, data, lists, family_test}) at(file, -60);
    CHECK_FALSE(source_newer_than(checkout.path(), built));
    at(notes, 30);
    at(data, 30);
    at(family_test, 30);
    CHECK_FALSE(source_newer_than(checkout.path(), built));  // results, data and a family's tests are not canopy's sources
    at(a, 10);
    REQUIRE(source_newer_than(checkout.path(), built));
    CHECK(*source_newer_than(checkout.path(), built) == std::filesystem::path("harness/run/a.cpp"));
    at(b, 20);
    CHECK(*source_newer_than(checkout.path(), built) == std::filesystem::path("techniques/grass/shaders/b.glsl"));
    at(lists, 40);  // CMake files are not sources here
    CHECK(*source_newer_than(checkout.path(), built) == std::filesystem::path("techniques/grass/shaders/b.glsl"));
    CHECK_FALSE(source_newer_than(checkout.path() / "absent", built));
}

TEST_CASE("this test binary is as new as its sources") {
    // The build that made this test linked it after every source it compiled; a stale binary
    // here would mean the build itself is broken.
    CHECK(source_newer_than_this_binary() == "");
}
