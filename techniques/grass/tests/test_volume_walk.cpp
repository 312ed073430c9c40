// The ray walk grass.volume's fragment shader runs (shaders/volume_walk.h, Lemme eq 5.7-5.21):
// over rays in every direction, entering anywhere, with 1 to 16 slices per direction, the planes
// it visits are exactly the slice planes the segment crosses, in order, each once, with the
// right slice index. Rays parallel to one direction's slices (eq 5.16 divides by zero there) and
// vertical rays (parallel to both) stay finite; the entry is found from outside and inside.
#include "../shaders/volume_walk.h"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace shader = canopy::shader;

namespace {

struct Crossing {
    float lambda;
    int axis, slice;
};

// Every slice plane (k + 0.5) / n of x and z that the segment e + lambda d, lambda in [0, 1],
// crosses, by brute force, sorted along the segment.
// `n`: the planes along x and along z (a macro-cell's n k and n l).
std::vector<Crossing> brute_force(glm::vec3 e, glm::vec3 d, glm::ivec2 n) {
    std::vector<Crossing> all;
    for (int axis = 0; axis < 2; ++axis) {
        const int c = axis == 0 ? 0 : 2;
        if (d[c] == 0.0f) continue;
        for (int k = 0; k < n[axis]; ++k) {
            const float lambda = ((float(k) + 0.5f) / float(n[axis]) - e[c]) / d[c];
            if (lambda >= 0.0f && lambda <= 1.0f) all.push_back({lambda, axis, k});
        }
    }
    std::sort(all.begin(), all.end(), [](const Crossing& a, const Crossing& b) { return a.lambda < b.lambda; });
    return all;
}

// The shader's loop: hits until the segment ends, at most 2n + 1 (as grass_volume.frag), or with
// different plane counts per axis n.x + n.y + 1 (as grass_volume_macro.frag).
std::vector<Crossing> walk(glm::vec3 e, glm::vec3 d, glm::ivec2 n) {
    const bool one_cell = n.x == n.y;
    const shader::VolumeWalk w = one_cell ? shader::volume_walk(e, d, float(n.x)) : shader::volume_walk(e, d, glm::vec2(n));
    std::vector<Crossing> hits;
    glm::ivec2 crossed(0);
    for (int i = 0; i < n.x + n.y + 1; ++i) {
        const shader::VolumeHit hit = one_cell ? shader::volume_next_hit(w, e, crossed, float(n.x))
                                               : shader::volume_next_hit(w, e, crossed, glm::vec2(n));
        REQUIRE(std::isfinite(hit.lambda));
        if (hit.lambda > 1.0f) break;
        crossed += hit.axis == 0 ? glm::ivec2(1, 0) : glm::ivec2(0, 1);
        hits.push_back({hit.lambda, hit.axis, hit.slice});
    }
    return hits;
}

std::vector<Crossing> walk(glm::vec3 e, glm::vec3 d, int n) { return walk(e, d, glm::ivec2(n)); }

// The segment from `e` (inside the unit cube) along `direction` to where it leaves the cube.
glm::vec3 to_exit(glm::vec3 e, glm::vec3 direction) {
    float t = 1e30f;
    for (int a = 0; a < 3; ++a) {
        if (direction[a] > 0.0f) t = std::min(t, (1.0f - e[a]) / direction[a]);
        if (direction[a] < 0.0f) t = std::min(t, -e[a] / direction[a]);
    }
    return t * direction;
}

void check_same(glm::vec3 e, glm::vec3 d, glm::ivec2 n) {
    CAPTURE(e.x);
    CAPTURE(e.y);
    CAPTURE(e.z);
    CAPTURE(d.x);
    CAPTURE(d.y);
    CAPTURE(d.z);
    CAPTURE(n.x);
    CAPTURE(n.y);
    const std::vector<Crossing> expected = brute_force(e, d, n);
    const std::vector<Crossing> got = walk(e, d, n);
    REQUIRE(got.size() == expected.size());
    for (size_t i = 0; i < got.size(); ++i) {
        CAPTURE(i);
        CHECK(got[i].lambda == doctest::Approx(expected[i].lambda).epsilon(1e-4));
        // Two planes met at the same point may come in either order.
        const bool tie = (i > 0 && std::abs(expected[i].lambda - expected[i - 1].lambda) < 1e-5f) ||
                         (i + 1 < got.size() && std::abs(expected[i].lambda - expected[i + 1].lambda) < 1e-5f);
        if (!tie) {
            CHECK(got[i].axis == expected[i].axis);
            CHECK(got[i].slice == expected[i].slice);
        }
        CHECK(got[i].slice >= 0);
        CHECK(got[i].slice < n[got[i].axis]);
    }
}

void check_same(glm::vec3 e, glm::vec3 d, int n) { check_same(e, d, glm::ivec2(n)); }

}  // namespace

TEST_CASE("volume walk: the planes met are the slice planes the segment crosses, in order, once each") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), signed_unit(-1.0f, 1.0f);
    int rays = 0;
    for (int n : {1, 2, 3, 8, 16}) {
        for (int i = 0; i < 2000; ++i) {
            const glm::vec3 e(unit(rng), unit(rng), unit(rng));
            glm::vec3 direction(signed_unit(rng), signed_unit(rng), signed_unit(rng));
            if (glm::length(direction) < 1e-3f) continue;
            check_same(e, to_exit(e, direction), n);
            ++rays;
        }
    }
    CHECK(rays > 9000);
}

TEST_CASE("volume walk: with as many planes per axis as a macro-cell of k x l cells has, the same holds") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), signed_unit(-1.0f, 1.0f);
    int rays = 0, met = 0;
    for (const glm::ivec2 n : {glm::ivec2(4, 8), glm::ivec2(16, 48), glm::ivec2(3, 1), glm::ivec2(256, 16)}) {
        for (int i = 0; i < 1000; ++i) {
            const glm::vec3 e(unit(rng), unit(rng), unit(rng));
            glm::vec3 direction(signed_unit(rng), signed_unit(rng), signed_unit(rng));
            if (glm::length(direction) < 1e-3f) continue;
            check_same(e, to_exit(e, direction), n);
            met += int(walk(e, to_exit(e, direction), n).size());
            ++rays;
        }
    }
    CHECK(rays > 3900);
    CHECK(met > 15 * rays);  // the walks do meet many planes
}

TEST_CASE("volume walk: rays entering through each face, going either way along each axis") {
    for (int n : {4, 16})
        for (float sx : {-1.0f, 1.0f})
            for (float sz : {-1.0f, 1.0f}) {
                // Entries on the faces the ray enters by, off the slice planes.
                const glm::vec3 direction(sx * 0.7f, -0.2f, sz * 0.4f);
                const glm::vec3 on_x_face(sx > 0.0f ? 0.0f : 1.0f, 0.9f, 0.37f);
                const glm::vec3 on_z_face(0.61f, 0.8f, sz > 0.0f ? 0.0f : 1.0f);
                const glm::vec3 on_top(0.23f, 1.0f, 0.71f);
                for (const glm::vec3 e : {on_x_face, on_z_face, on_top}) {
                    const std::vector<Crossing> hits = walk(e, to_exit(e, direction), n);
                    CHECK(!hits.empty());
                    check_same(e, to_exit(e, direction), n);
                }
            }
}

TEST_CASE("volume walk: rays parallel to one direction's slices, or to both, stay finite and meet only the others") {
    for (int n : {1, 4, 16}) {
        // Along x (d.z = 0, eq 5.16's w_z is 0/0 or x/0): only planes x = const, all of them.
        for (float z : {0.3f, 0.5f, 0.125f + 0.5f / 16.0f}) {  // the last on a slice plane of n = 16
            const glm::vec3 e(0.0f, 0.5f, z);
            const std::vector<Crossing> hits = walk(e, glm::vec3(1.0f, -0.2f, 0.0f), n);
            REQUIRE(hits.size() == size_t(n));
            for (int k = 0; k < n; ++k) {
                CHECK(hits[size_t(k)].axis == 0);
                CHECK(hits[size_t(k)].slice == k);
            }
            check_same(e, glm::vec3(1.0f, -0.2f, 0.0f), n);
        }
        // Along -z: planes z = const from the far end down.
        const std::vector<Crossing> back = walk(glm::vec3(0.4f, 0.5f, 1.0f), glm::vec3(0.0f, 0.0f, -1.0f), n);
        REQUIRE(back.size() == size_t(n));
        for (int k = 0; k < n; ++k) {
            CHECK(back[size_t(k)].axis == 1);
            CHECK(back[size_t(k)].slice == n - 1 - k);
        }
        // Straight down: parallel to every slice, it meets none.
        CHECK(walk(glm::vec3(0.5f, 1.0f, 0.5f), glm::vec3(0.0f, -1.0f, 0.0f), n).empty());
        CHECK(walk(glm::vec3(0.5f / float(n), 1.0f, 0.5f / float(n)), glm::vec3(0.0f, -1.0f, 0.0f), n).empty());
        // Nearly parallel (below VOLUME_PARALLEL): treated as parallel, still finite.
        CHECK(walk(glm::vec3(0.5f, 1.0f, 0.5f), glm::vec3(1e-8f, -1.0f, -1e-8f), n).empty());
    }
}

TEST_CASE("volume entry: where the eye's segment enters the cube, 0 for an eye inside") {
    CHECK(shader::volume_entry(glm::vec3(0.5f), glm::vec3(0.3f, -0.2f, 0.1f)) == 0.0f);
    // From x = -1 to the far face x = 1 along x: enters half way.
    CHECK(shader::volume_entry(glm::vec3(-1.0f, 0.5f, 0.5f), glm::vec3(2.0f, 0.0f, 0.0f)) == doctest::Approx(0.5f));
    // From above and to the side: the later of the two slabs' near faces.
    const glm::vec3 eye(-1.0f, 3.0f, 0.5f), exit(1.0f, 0.0f, 0.5f);
    const float t = shader::volume_entry(eye, exit - eye);
    const glm::vec3 entry = eye + t * (exit - eye);
    CHECK(entry.y == doctest::Approx(1.0f));
    CHECK(entry.x == doctest::Approx(1.0f / 3.0f));
    // A vertical segment from above: only the y slab bounds it.
    CHECK(shader::volume_entry(glm::vec3(0.5f, 5.0f, 0.5f), glm::vec3(0.0f, -5.0f, 0.0f)) == doctest::Approx(0.8f));
}
