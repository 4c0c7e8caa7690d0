#version 460
#extension GL_GOOGLE_include_directive : require
// Stage 4: any-hit visibility of each light sample; an unoccluded one adds its contribution to its path.
// With one light sample per path and bounce a plain add is race-free; splitting (several samples per path)
// builds the VKMC_FLOAT_ATOMICS variant, which adds atomically. Built twice, as intersect is (VKMC_DEEP_PASS).
#ifdef VKMC_FLOAT_ATOMICS
#extension GL_EXT_shader_atomic_float : require
#endif
#include "common.glsl"
#include "traversal.glsl"
#include "deferred_walk.glsl"

void main() {
  uint slot;
  if (!walkItem(control.shadowQueueCount, slot)) return;
  ShadowRay s = loadShadowRay(slot);
  vec4 h;
  bool complete;
  walkRayKey = floatBitsToUint(s.contribution.w);
  if (!traceItem(slot, s.origin.xyz, s.direction.xyz, kShadowRayTMax, true, h, complete)) return;
  if (!complete) {  // as in intersect: counted, and the sample poisoned
    atomicAdd(control.walksCut, 1u);
    s.contribution.rgb = vec3(uintBitsToFloat(0x7fc00000u));
  } else if (floatBitsToUint(h.w) != kMissPrimitive) {
    return;
  }
  uint id = floatBitsToUint(s.direction.w);  // the root path of the sample
#ifdef VKMC_FLOAT_ATOMICS
  // EARS trains on what each path copy gathered: the slot that sampled the light (origin.w) sums it.
  // A copy's first light sample (tagged) also turns its record's pending factor into the sample's v; one whose
  // contribution is not finite (or whose walk was cut) teaches nothing.
  if (kRouletteMode == kRouletteEars && earsTrains()) {
    uint tag = floatBitsToUint(s.origin.w);
    bool finite = allFinite(s.contribution.rgb);
    if (finite) {
      uint vertexSlot = tag & kEarsSlotMask;
      atomicAdd(earsSlots[vertexSlot].gathered.r, s.contribution.r);
      atomicAdd(earsSlots[vertexSlot].gathered.g, s.contribution.g);
      atomicAdd(earsSlots[vertexSlot].gathered.b, s.contribution.b);
    }
    if (kEarsLightMax > 0.0 && (tag & kEarsFirstLightTag) != 0u) {
      uint r = earsLightRecord(earsTaggedRecord(tag));
      earsRecordVec4s[r] = finite ? vec4(s.contribution.rgb * earsRecordVec4s[r].rgb, kEarsLightUnoccluded)
                                  : vec4(0.0, 0.0, 0.0, kEarsLightNone);
    }
  }
  atomicAdd(paths[id].radiance.r, s.contribution.r);
  atomicAdd(paths[id].radiance.g, s.contribution.g);
  atomicAdd(paths[id].radiance.b, s.contribution.b);
#else
  vec4 radiance = loadRadiance(id);
  storeRadiance(id, vec4(radiance.rgb + s.contribution.rgb, radiance.w));
#endif
}
