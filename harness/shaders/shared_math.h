// Lets one header compile as GLSL (450) and as C++20 with glm, so unit tests check the very
// code the shaders run. Write shared functions with `f`-suffixed literals, glm/GLSL builtins
// only, and CANOPY_FN in front of every function.
#ifndef CANOPY_SHARED_MATH_H
#define CANOPY_SHARED_MATH_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#define CANOPY_FN inline
#define CANOPY_BEGIN_NAMESPACE namespace canopy::shader { using namespace glm;
#define CANOPY_END_NAMESPACE }
#define CANOPY_CONST constexpr
#else
#define CANOPY_FN
#define CANOPY_BEGIN_NAMESPACE
#define CANOPY_END_NAMESPACE
#define CANOPY_CONST const
#endif

#endif
