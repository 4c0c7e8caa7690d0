// EARS at one vertex of the wavefront (shared/ears.h): the factor q from the vertex's cache cell, then
// floor(q + u) copies of the vertex's estimate, its light samples and its BSDF continuation, each weighted 1/q.
// Copy 0 runs in the vertex's own invocation; the others take pool slots and run one per invocation in a second
// dispatch over the copy queue (kernels/ears_copies.comp), so a lane that splits 20 ways does not hold its SIMD
// group for 20 iterations. Each copy at a training depth leaves a record (EarsRecord) that the pass's end fills
// with what its subtree gathered (kernels/ears_*.comp). Needs shade_output.glsl.

#ifdef VKMC_FLOAT_ATOMICS  // EARS runs the atomic variants only (its copies add to shared roots)
layout(binding = BINDING_EARS_SAMPLING, TEXEL_FORMAT_EARS_SAMPLING) uniform readonly imageBuffer earsLearned;

// The copy queue: the third region of BINDING_RAY_QUEUES. A queued slot holds the vertex's path (before its
// factor); its radiance field, unused by a split child, carries (q, copy index bits, parent slot bits, qL). The
// copy reads the vertex's hit from the parent's slot, which no stage rewrites before the next bounce's intersect.
uint copyQueueBase() { return 2u * pc.queueCapacity; }

// Takes n entries of the copy queue for a vertex's copies: one atomic per subgroup, outside the copy loop.
uint copyQueueSlots(uint n) {
  uint total = subgroupAdd(n), base = 0u;
  if (subgroupElect()) base = atomicAdd(control.copyQueueCount, total);
  return copyQueueBase() + subgroupBroadcastFirst(base) + subgroupExclusiveAdd(n);
}

// What a vertex's cell learned, its levels resolved by the fold (ears.h earsResolveLevel): for its copies
// (moment, variance: per cost) and for their light samples (the light cell beside it).
struct EarsReading {
  vec3 moment, variance;
  float copies;
  vec3 lightMoment, lightVariance;
  float lightSamples;
};

// A vertex reads one cell, its finest (three hashed reads cost ~30 ns a vertex on lavapipe, docs/journal/ears.md). One
// the fold has not resolved (no key had reached it) reads zero copies (throughput roulette) and leaves its key,
// so that the next fold resolves it from its coarser levels; one whose slot was resolved for another key (the
// table's slots collide) reads nothing either, and leaves the slot to that key.
EarsReading earsRead(uint key) {
  EarsReading r = EarsReading(vec3(0.0), vec3(0.0), 0.0, vec3(0.0), vec3(0.0), 0.0);
  if (!(earsHeader.imageFactor > 0.0)) return r;
  uint cell = earsCellIndex(key, 0u, earsHeader.cellMask);
  vec4 m = imageLoad(earsLearned, int(kEarsSamplingTexels * cell));
  vec4 v = imageLoad(earsLearned, int(kEarsSamplingTexels * cell + 1u));
  if (!(m.w > 0.0)) earsCellWords[earsKeyWord(cell, earsTableCells())] = key + 1u;
  if (!earsResolvedFor(v, key)) return r;
  r = EarsReading(m.rgb, v.rgb, m.w, vec3(0.0), vec3(0.0), 0.0);
  if (kEarsLightMax > 0.0) {
    uint light = earsLightCell(cell, earsHeader.cellMask);
    vec4 l = imageLoad(earsLearned, int(kEarsSamplingTexels * light));
    r.lightMoment = l.rgb;
    r.lightVariance = imageLoad(earsLearned, int(kEarsSamplingTexels * light + 1u)).rgb;
    r.lightSamples = l.w;
  }
  return r;
}

// The vertex's relative throughput t = beta / sqrt(I^2 + eps) per channel (the pixel's smoothed estimate I).
vec3 earsRelativeThroughput(PathState path) {
  vec3 estimate = loadPixelEstimate(pathPixelOf(path.pixel)).rgb;
  return path.throughput.rgb / sqrt(estimate * estimate + earsHeader.epsilon);
}

// The factor at a vertex from its cells once one of them has learned enough, and whether one had; throughput
// roulette (the sqrt rule, judged by the throughput that reaches the vertex) where none has.
float earsVertexFactor(PathState path, EarsReading r, vec3 t, out bool trained) {
  trained = r.copies >= kEarsMinCellCopies && earsHeader.imageFactor > 0.0;
  float q = 1.0;
  if (trained) {
    q = min(earsFactor(t, r.moment, r.variance, earsHeader.imageFactor), kEarsMaxFactor);
  } else if (rouletteApplies(path.depth, kRouletteDepth)) {
    q = rouletteSurvival(sqrt(maxComponent(path.throughput.rgb) * path.throughput.w * path.origin.w), 1.0, kRouletteMaxSurvival);
  }
  return path.depth >= kEarsNoSplitDepth ? min(q, kRouletteMaxSurvival) : q;
}

// The light factor qL of each copy of a vertex whose copies carry throughput beta / q, once its light cells have
// learned enough; 0 where they have not (the copy then takes light_samples, as without EARS).
float earsLightFactor(EarsReading r, vec3 t, float q) {
  if (kEarsLightMax == 0.0 || !(r.lightSamples >= kEarsMinCellCopies && earsHeader.imageFactor > 0.0)) return 0.0;
  return min(earsFactor(t / q, r.lightMoment, r.lightVariance, earsHeader.imageFactor), kEarsLightMax);
}

// Appends to the training lists, one atomic per subgroup (call where the appending lanes are the active ones).
uint appendTrainingRecord() {
  uint n = subgroupAdd(1u), base = 0u;
  if (subgroupElect()) base = atomicAdd(earsHeader.trainingRecords, n);
  return appendSlot(base);
}
uint appendTrainingChild() {
  uint n = subgroupAdd(1u), base = 0u;
  if (subgroupElect()) base = atomicAdd(earsHeader.trainingChildren, n);
  return earsChildList() + appendSlot(base);
}

// The vertex's factor into its histogram (kEarsFactorHistogram) by depth, added at the kernel's end by
// flushEarsDecisions: a subgroup's four bins in one atomic site, lane b adding bin b (a bounce's paths all have the
// same depth; the subgroup has at least kEarsBins = kRareCounters lanes). Called from main's top level.
uint earsDecisionBin = kEarsBins, earsDecisionRow = 0u;  // kEarsBins: no decision
void countEarsFactor(uint depth, uint bin) {
  earsDecisionRow = (kEarsFactorHistogram * kEarsHistogramDepths + min(depth, kEarsHistogramDepths - 1u)) * kEarsBins;
  earsDecisionBin = bin;
}
void flushEarsDecisions() {
  uvec4 n = subgroupAdd(uvec4(equal(uvec4(earsDecisionBin), uvec4(0u, 1u, 2u, 3u))));
  uint row = subgroupMax(earsDecisionBin < kEarsBins ? earsDecisionRow : 0u);
  uint lane = gl_SubgroupInvocationID;
  if (lane < kEarsBins && n[lane] > 0u) atomicAdd(earsHeader.histograms[row + lane], n[lane]);
}

// A copy's light factor into its histogram (kEarsLightHistogram) by depth: one atomic per subgroup and bin.
void countEarsDecision(uint histogram, uint depth, uint bin) {
  uint row = (histogram * kEarsHistogramDepths + min(depth, kEarsHistogramDepths - 1u)) * kEarsBins;
  for (uint b = 0u; b < kEarsBins; ++b) {
    uint n = subgroupAdd(bin == b ? 1u : 0u);
    if (subgroupElect() && n > 0u) atomicAdd(earsHeader.histograms[row + b], n);
  }
}

// How many light samples a copy takes, and the weight of each: floor(qL + u) weighted 1/qL where its light
// cells decided (splitting past light_samples only with shadow-queue slots reserved before the draw), else
// light_samples weighted 1/light_samples.
uint earsLightSamples(PathState copy, inout float qL, out float share) {
  uint base = lightSamplesAt(copy.depth);
  if (!(qL > 0.0)) {
    share = 1.0 / float(base);
    return base;
  }
  uint extra = kEarsLightMax > 1.0 && uint(ceil(qL)) > base ? uint(ceil(qL)) - base : 0u;
  if (extra > 0u && atomicAdd(control.extraShadowRays, extra) + extra > earsHeader.extraShadowSlots) qL = float(base);
  share = 1.0 / qL;
  return splitCount(qL, sampleU(pathStream(copy), bounceDim(copy.depth, kDimLightSplit)));
}

// Copy c of the vertex of `path` (its throughput before the factor) in slot `target`, split off from `parent`'s:
// its record, its light samples (qL: earsLightFactor) and its BSDF continuation, each weighted 1/q. `emission`:
// what the hit itself sends back (copy 0 only), which the caller adds with the copy's results (addToEarsSample)
// and which belongs to the vertex before. Returns the rays the copy traced and, in `poisoned`, a non-finite
// throughput to add (counted by continuePath).
float shadeEarsCopy(PathState path, uint target, uint parent, SurfacePoint s, GltfMaterial gm, vec3 wo, vec3 woLocal,
                    float q, float qL, uint c, uint key, vec3 emission, out vec3 poisoned) {
  uint depth = path.depth;
  bool trains = earsTrains();
  if (c > 0u && trains) {
    earsSlots[target] = EarsSlot(vec4(0.0), parent + 1u, depth, 0u, 0u);
    earsTrainingList[appendTrainingChild()] = target;
  }
  vec3 beta = path.throughput.rgb;
  bool records = trains && depth < kEarsDepths && maxComponent(beta) > 0.0;
  PathState copy = path;
  copy.rngKey = childKey(path.rngKey, depth, c);
  copy.throughput.rgb /= q;
  uint rays = 0u;
  float share = 1.0;
  uint samples = kHasLights != 0u && kNee != 0u ? earsLightSamples(copy, qL, share) : 0u;  // qL as it ran
  if (kEarsLightMax > 0.0 && kHasLights != 0u && kNee != 0u) countEarsDecision(kEarsLightHistogram, depth, earsBin(qL > 0.0, qL));
  float firstLight = samples > 0u ? kEarsLightNoRay : kEarsLightNone;
  for (uint j = 0u; j < samples; ++j) {
    ShadowRay ray;
    if (prepareLightSample(copy, target, s, gm, wo, j, lightSamplesAt(depth), share, ray)) {
      if (kEarsLightMax > 0.0 && j == 0u && records) {
        ray.origin.w = uintBitsToFloat(earsFirstLightTag(target, depth));
        firstLight = kEarsLightTraced;
      }
      storeShadowRay(shadowQueueSlot(), ray);
      ++rays;
    }
  }
  if (records) {
    vec3 scale = vec3(beta.r > 0.0 ? q / beta.r : 0.0, beta.g > 0.0 ? q / beta.g : 0.0, beta.b > 0.0 ? q / beta.b : 0.0);
    uint record = target * kEarsDepths + depth;
    vec4 before = earsSlots[target].gathered + vec4(allFinite(emission) ? emission : vec3(0.0), 0.0);
    earsRecords[record] = EarsRecord(-before, vec4(scale, uintBitsToFloat(key + 1u)));
    earsTrainingList[appendTrainingRecord()] = record;
    if (kEarsLightMax > 0.0) earsRecordVec4s[earsLightRecord(record)] = vec4(scale / share, firstLight);
  }
  poisoned = vec3(0.0);
  PathState next;
  if (continuationIsUseful(depth) && continuePath(path, target, s, gm, woLocal, c, q, poisoned, next)) {
    queueContinuation(target, next, c > 0u);
    ++rays;
  }
  return float(rays);
}

// The vertex of `path` (slot id) at surface point s: its factor, its copies queued, copy 0 shaded here; its results and
// the hit's emission added to the sample once.
void shadeEarsVertex(PathState path, uint id, SurfacePoint s, GltfMaterial gm, vec3 wo, vec3 woLocal,
                     vec3 emission) {
  uint depth = path.depth;
  vec3 poisoned = vec3(0.0);
  float rays = 0.0;
  if (belowDepthCap(depth)) {
    uint key = earsCellKey(s.p, s.ng, earsHeader.grid);
    EarsReading reading = earsRead(key);
    // The pixel estimate is read only where a cell will use it (as before the light cells).
    bool learned = max(reading.copies, reading.lightSamples) >= kEarsMinCellCopies;
    vec3 t = learned ? earsRelativeThroughput(path) : vec3(0.0);
    bool trained;
    float q = earsVertexFactor(path, reading, t, trained);
    // Slots for every copy but the first are taken before the copies are drawn, so whether the pool was full
    // (then q = 1: the vertex as it is) never depends on the draw: unbiased.
    uint spare = uint(ceil(q)) - 1u, firstChild = 0u;
    if (spare > 0u && !reserveChildSlots(spare, firstChild)) {
      q = 1.0;
      spare = 0u;
    }
    uint copies = min(splitCount(q, sampleU(pathStream(path), bounceDim(depth, kDimSplit))), spare + 1u);
    countEarsFactor(depth, earsBin(trained, q));
    float qL = earsLightFactor(reading, t, q);
    uint queued = copyQueueSlots(copies > 1u ? copies - 1u : 0u);
    for (uint c = 1u; c < copies; ++c) {
      uint target = firstChild + c - 1u;
      PathState child = path;
      child.radiance = vec4(q, uintBitsToFloat(c), uintBitsToFloat(id), qL);
      storePath(target, child);
      rayQueues[queued + c - 1u] = target;
    }
    if (copies > 0u) rays = shadeEarsCopy(path, id, id, s, gm, wo, woLocal, q, qL, 0u, key, emission, poisoned);
  }
  // The slot trains on the emission even where the continuation poisoned the sample (its record counted it).
  addToEarsSample(id, path.rootPath, emission + poisoned, emission, rays);
}
#endif
