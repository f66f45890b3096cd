#version 460
// BDPT's camera pass as a wavefront: one launch of its path kernel (glsl/common/bdpt_camera_wavefront.glsl).
#include "bdpt_camera_wavefront.glsl"
