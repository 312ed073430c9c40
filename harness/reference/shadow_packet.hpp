// Shadow rays traced 16 at a time. A shading point's samples towards one light share their
// origin, so a packet is coherent and Embree's 16-wide traversal (AVX-512 where available) pays
// (see shadow_ray_benchmark.hpp), except where it hangs (ShadowQuery, below).
#pragma once

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <limits>

namespace canopy {

// Every lane of a packet is a well-formed ray from construction on, traced or not: Embree reads
// the lanes it is told to skip too (its AVX2 path splits a 16-wide packet into two 8-wide ones
// and asserts that every lane of each half is a valid ray), so a lane of leftover stack data
// aborts the process on one CPU and passes on another (issue 7).
struct alignas(64) ShadowPacket {
    static constexpr int kWidth = 16;

    RTCRay16 rays;
    alignas(64) int valid[kWidth] = {};  // -1 = trace this lane, 0 = skip it
    int active = 0;                 // lanes with valid == -1

    // All lanes start at `origin`, untraced, with an empty segment along +z.
    explicit ShadowPacket(glm::vec3 origin = glm::vec3(0.0f)) {
        for (int lane = 0; lane < kWidth; ++lane) set(lane, origin, glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, false);
    }

    // Sets lane `lane` to the segment origin + t * direction, t in [0, t_far]; `trace` false
    // leaves the lane out. After tracing, occluded(lane) tells the result.
    void set(int lane, glm::vec3 origin, glm::vec3 direction, float t_far, bool trace) {
        rays.org_x[lane] = origin.x;
        rays.org_y[lane] = origin.y;
        rays.org_z[lane] = origin.z;
        rays.dir_x[lane] = direction.x;
        rays.dir_y[lane] = direction.y;
        rays.dir_z[lane] = direction.z;
        rays.tnear[lane] = 0.0f;
        rays.tfar[lane] = t_far;
        rays.time[lane] = 0.0f;
        rays.mask[lane] = 0xffffffffu;
        rays.id[lane] = unsigned(lane);
        rays.flags[lane] = 0;
        active += (trace ? 1 : 0) - (valid[lane] != 0 ? 1 : 0);
        valid[lane] = trace ? -1 : 0;
    }
    // Embree sets tfar to -inf on an occluded ray.
    bool occluded(int lane) const { return valid[lane] != 0 && rays.tfar[lane] < 0.0f; }
};

// How a tracer hands Embree a packet: as one 16-wide query (rtcOccluded16), or lane by lane
// (rtcOccluded1). Embree 3.13's 16-wide occlusion kernel was caught four times looping forever
// inside the call on a grass field (instanced copies with filter functions, AVX-512), now and then
// (its BVH builds differ from run to run), never on scenes of plain triangles; one ray at a time it
// is 2.2 times slower here for the shadow family's references (bench reference on spheres: 5.2e7
// against 1.15e8 rays/s), which do not need it. EmbreeScene::shadow_query picks.
enum class ShadowQuery { packet16, single };

// Traces packets against a scene and counts the rays actually traced.
class EmbreeShadowTracer {
public:
    explicit EmbreeShadowTracer(RTCScene scene, ShadowQuery query = ShadowQuery::packet16)
        : scene_(scene), query_(query) {
        rtcInitIntersectContext(&context_);
        context_.flags = query == ShadowQuery::packet16 ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                                        : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    }
    void trace(ShadowPacket& packet) {
        if (packet.active == 0) return;
        rays_ += uint64_t(packet.active);
        if (query_ == ShadowQuery::packet16) {
            rtcOccluded16(packet.valid, scene_, &context_, &packet.rays);
            return;
        }
        for (int lane = 0; lane < ShadowPacket::kWidth; ++lane) {
            if (packet.valid[lane] == 0) continue;
            RTCRay ray;
            ray.org_x = packet.rays.org_x[lane];
            ray.org_y = packet.rays.org_y[lane];
            ray.org_z = packet.rays.org_z[lane];
            ray.dir_x = packet.rays.dir_x[lane];
            ray.dir_y = packet.rays.dir_y[lane];
            ray.dir_z = packet.rays.dir_z[lane];
            ray.tnear = packet.rays.tnear[lane];
            ray.tfar = packet.rays.tfar[lane];
            ray.time = packet.rays.time[lane];
            ray.mask = packet.rays.mask[lane];
            ray.id = packet.rays.id[lane];
            ray.flags = packet.rays.flags[lane];
            rtcOccluded1(scene_, &context_, &ray);
            packet.rays.tfar[lane] = ray.tfar;
        }
    }
    uint64_t rays() const { return rays_; }

private:
    RTCScene scene_;
    ShadowQuery query_;
    RTCIntersectContext context_{};
    uint64_t rays_ = 0;
};

}  // namespace canopy
