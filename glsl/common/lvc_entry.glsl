// The light vertex cache's entries (BIND_LVC_INDEX), written by lvc_compact.comp, read by the
// camera passes' connections (bdpt_camera_step.glsl, bdpt_camera_path.glsl) and VCM's merge grid.
#ifndef BIDIR_LVC_ENTRY_GLSL
#define BIDIR_LVC_ENTRY_GLSL

// Each connection's vertex resampled from this many uniform draws
// (RenderSettings::connection_candidates; connect_resampled in bdpt_camera_path.glsl).
layout(constant_id = SPEC_LVC_CANDIDATES) const uint LVC_CANDIDATES = 1u;

// 16-byte words of an entry: (slot, its path's seen / stored as float bits, -, -); where
// connections are resampled, a second word previews the vertex for the resampling's target, so
// a candidate is one read of 32 bytes, shared by the lanes that connect with its group where
// the subgroup's lanes can serve all its groups (connect_resampled): the first word's z holds the shading normal octahedral in 2 x 12 bits
// and the lobe pick in the top 8, its w dVCM + dVC mis(reverse pdf), the light side's MIS sum
// taken as diffuse; the second word is (pos, luminance of beta f).
const uint LVC_ENTRY_WORDS = LVC_CANDIDATES > 1u ? LVC_ENTRY_WORDS_RESAMPLED : LVC_ENTRY_WORDS_UNIFORM;

#endif
