#version 460
// Miss shader of the driver's ray-tracing yardstick (trace.rgen).
#extension GL_EXT_ray_tracing : require
#include "bidir_abi.glsl"
#include "payload.glsl"

layout(location = 0) rayPayloadInEXT RtPayload payload;

void main() {
    payload.prim = NO_HIT;
}
