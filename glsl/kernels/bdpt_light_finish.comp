#version 460
// BDPT's light pass as a wavefront, its finishing launch: each listed path runs to its end,
// tracing its own rays (glsl/common/bdpt_light_wavefront.glsl with BDPT_WF_FINISH).
#define BDPT_WF_FINISH
#include "bdpt_light_wavefront.glsl"
