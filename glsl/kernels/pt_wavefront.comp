#version 460
// The wavefront path tracer: one launch of its path kernel (glsl/common/pt_wavefront.glsl).
#include "pt_wavefront.glsl"
