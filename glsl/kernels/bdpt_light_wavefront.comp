#version 460
// BDPT's light pass as a wavefront: one launch of its path kernel (glsl/common/bdpt_light_wavefront.glsl).
#include "bdpt_light_wavefront.glsl"
