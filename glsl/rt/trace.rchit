#version 460
// Closest hit of the driver's ray-tracing yardstick (trace.rgen).
#extension GL_EXT_ray_tracing : require
#include "payload.glsl"

layout(location = 0) rayPayloadInEXT RtPayload payload;
hitAttributeEXT vec2 bary;

void main() {
    payload = RtPayload(gl_HitTEXT, uint(gl_PrimitiveID), bary);
}
