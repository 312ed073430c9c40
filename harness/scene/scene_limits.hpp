// The ranges scene values must lie in, checked when a scene is loaded (configs/README.md,
// "Limits"). Both renderers compute in single precision: within these ranges their float math
// stays finite (the reference's variance squares the emitted power) and positions keep a
// precision of a few centimetres or better. Embree itself accepts coordinates up to about 1.8e18,
// but float spacing is already 0.06 at 1e6 and shadow-ray offsets grow with it.
#pragma once

namespace canopy::limits {

// |x|, |y|, |z| of every world-space vertex, light position, camera position and target, and of
// every `translate`.
inline constexpr double kMaxCoordinate = 1e6;

// Camera clip distances: the far plane reaches the corners of the coordinate cube.
inline constexpr double kMinNear = 1e-6;
inline constexpr double kMaxFar = 1e7;

// |scale| of each component of one transform (an object's or an instance's).
inline constexpr double kMinScale = 1e-3;
inline constexpr double kMaxScale = 1e3;
// |determinant| of an instance's whole linear transform (instance · object): how much it scales
// volumes. Below it the reference calls the object flat.
inline constexpr double kMinVolumeScale = 1e-9;

// Light `intensity` (W/sr, or W/m² for a directional light) and each component of its `color`.
inline constexpr double kMaxIntensity = 1e6;
inline constexpr double kMaxColor = 100.0;
// A rect light's width and height, a sphere light's radius: radiance is intensity / area.
inline constexpr double kMinLightSize = 1e-4;
inline constexpr double kMaxLightSize = 1e4;

// Each component of the scene's `ambient` and `background` radiance.
inline constexpr double kMaxRadiance = 1e6;

// A [[population]]'s `count` (the reference holds one Embree instance per copy, in each of its two
// scenes), and its prototype's triangles, which the reference and the GPU store once (about 100
// bytes each, with the BVH); the copies' triangles together are not limited.
inline constexpr long long kMaxPopulationCount = 1000000;
// A heightfield's grid vertices a side: 2048 x 2048 is 8.4 M triangles, drawn and ray-traced flat.
inline constexpr long long kMaxHeightFieldVertices = 2048;
inline constexpr double kMaxPrototypeTriangles = 2e7;

}  // namespace canopy::limits
