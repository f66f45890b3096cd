#version 460
// The wavefront path tracer, a pass's finishing launch: each slot runs the rest of its samples,
// tracing its own rays (glsl/common/pt_wavefront.glsl with PT_WF_FINISH).
#define PT_WF_FINISH
#include "pt_wavefront.glsl"
