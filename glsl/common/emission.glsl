// Emission textures at light samples: emitters are chosen by the power of their emission
// factor (lights.glsl); the radiance at the sampled point is that factor times the emission
// texture there. Needs scene.glsl (textures) and lights.glsl (LightSample).
#ifndef BIDIR_EMISSION_GLSL
#define BIDIR_EMISSION_GLSL

layout(std430, binding = BIND_EMITTER_UVS) readonly buffer EmitterUvs { GpuEmitterUv emitter_uvs[]; };

vec3 light_sample_radiance(LightSample ls) {
    if (HAS_EMISSION_TEXTURES == 0u) {
        return ls.le;
    }
    GpuEmitterUv e = emitter_uvs[ls.emitter];
    if (e.texture == 0u) {
        return ls.le;
    }
    vec2 uv = (1.0 - ls.bary.x - ls.bary.y) * e.uv0 + ls.bary.x * e.uv1 + ls.bary.y * e.uv2;
    return ls.le * sample_texture(e.texture - 1u, uv).rgb;
}

#endif
