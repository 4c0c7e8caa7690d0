// Efficiency-aware Russian roulette and splitting (EARS: Rath, Grittmann, Herholz, Weier, Slusallek 2022), on the
// device: the cache's encodings and its pure functions, shared by the kernels (ears_shade.glsl, kernels/ears_*.comp)
// and the host's tests.
//
// At a vertex of throughput beta in a pixel whose estimate is I, per channel t = beta / sqrt(I^2 + eps) (eps:
// relMSE's), the factor q = sqrt(mean over channels of t^2 E[Lr^2] / C) sqrt(C_img / V_img) maximizes the
// efficiency 1 / (V T) of the image's relMSE: Lr is what one copy of the vertex's estimate (its light samples and
// its BSDF continuation) gathers per unit throughput and C the rays it costs, both learned per cache cell;
// C_img / V_img is the image's rays per sample over its relative variance per sample. The vertex is then taken
// floor(q + u) times, each copy weighted 1/q: q < 1 is roulette, q > 1 splitting (roulette.h splitCount), unbiased
// for any q chosen before the copies are drawn. Every sample decides with what other samples taught the cache (a
// pass's training samples run first, as a wavefront of their own), never with its own.
// The same rule decides each copy's light samples (MARS's per-technique factors, Rath et al. 2024): a second set
// of cells learns what one light sample gathers per unit throughput (v) and the rays it costs, and the copy takes
// floor(qL + u) light samples, each weighted 1/qL: qL < 1 is shadow-ray roulette, qL > 1 light-sample splitting.
#ifndef VKMC_EARS_H
#define VKMC_EARS_H
#include "glsl_cpp.h"
#include "rng.h"  // hashU32
VKMC_BEGIN_NAMESPACE

VKMC_CONST uint kEarsDepths = 4u;         // vertices of a path that train the cache (deeper ones read it)
VKMC_CONST float kEarsFactorMin = 0.05f;  // EARS's clamp of q
VKMC_CONST float kEarsFactorMax = 20.0f;
VKMC_CONST float kEarsOutlierShare = 0.001f;   // V_img leaves out this share of its noisiest pixels (EARS: 10 samples)
VKMC_CONST float kEarsMinCellCopies = 256.0f;  // a vertex decides once one of its cells has learned from this many
VKMC_CONST float kEarsShrinkCopies = 1024.0f;  // a level's moments count half against the coarser ones' at this many
VKMC_CONST uint kEarsLevels = 3u;              // grids of 64, 16 and 4 cells along the longest side
VKMC_CONST uint kEarsLevelShift = 2u;
VKMC_CONST uint kEarsNoSplitDepth = 64u;    // from this depth on q <= kRouletteMaxSurvival: every path ends
VKMC_CONST uint kEarsGridResolution = 64u;  // cells along the scene's longest side
VKMC_CONST uint kEarsBins = 4u;             // factor histogram: untrained (fallback), q < 1, q = 1, q > 1
VKMC_CONST uint kEarsBinFallback = 0u, kEarsBinRoulette = 1u, kEarsBinOne = 2u, kEarsBinSplit = 3u;
VKMC_CONST float kEarsEpsilon = 0.01f;        // relMSE's epsilon (analysis/error_metrics.h; ears_test checks)
VKMC_CONST uint kEarsTrainingPaths = 16384u;  // samples of a pass that train the cache (earsTrainingSamples)
VKMC_CONST uint kEarsHistogramDepths = 8u;    // histogram rows (the last counts every deeper vertex)
VKMC_CONST uint kEarsFactorHistogram = 0u, kEarsLightHistogram = 1u;  // EarsHeader histograms
VKMC_CONST float kEarsLightFactorMax = 8.0f;  // light samples a copy takes at most (the SIMD group waits for its
                                              // lane with the most)
// The first light sample of a training copy tags its shadow ray (ShadowRay origin.w: the copy's slot, its depth in
// bits 29-30, this bit) so that the shadow stage can fill the copy's light record (earsLightRecord).
VKMC_CONST uint kEarsFirstLightTag = 0x80000000u;
VKMC_CONST uint kEarsTagDepthShift = 29u;
VKMC_CONST uint kEarsSlotMask = (1u << kEarsTagDepthShift) - 1u;
// EarsRecord light.w: what became of the copy's first light sample.
VKMC_CONST float kEarsLightNone = 0.0f;        // no light sample: nothing to learn
VKMC_CONST float kEarsLightNoRay = 1.0f;       // sampled, but nothing to trace (v = 0, no ray)
VKMC_CONST float kEarsLightTraced = 2.0f;      // traced, occluded unless the shadow stage said otherwise (v = 0, 1 ray)
VKMC_CONST float kEarsLightUnoccluded = 3.0f;  // traced and unoccluded: rgb is v (1 ray)

// The cache's parameters, written by the host between passes, and the factor histogram the kernels count.
struct EarsHeader {
  vec4 grid;              // xyz: the grid's origin, w: cells per unit length
  uint cellMask;          // cells - 1 (a power of two)
  float imageFactor;      // sqrt(C_img / V_img) of the passes so far; 0: nothing learned yet (throughput roulette)
  float epsilon;          // t = beta / sqrt(I^2 + epsilon)
  uint extraShadowSlots;  // shadow-queue slots beyond light_samples per path slot, for split light samples
  // The training lists of the pass (BINDING_EARS_TRAINING): records written, then slots split off by training
  // paths, so that the training kernels visit those alone; the host empties them after each pass's training.
  uint trainingRecords;
  uint trainingChildren;
  uint unused0, unused1;
  // Two histograms by depth and bin: the vertices' factors (kEarsFactorHistogram), the copies' light factors
  // (kEarsLightHistogram).
  uint histograms[2u * kEarsHistogramDepths * kEarsBins];
};

// One cell: the sums its training copies added over every pass so far. The table holds the copies' cells, then
// as many light cells (earsLightCell) whose sums are those of the copies' first light samples: rgb v, w samples;
// v^2, w rays.
struct EarsCell {
  vec4 sum;         // rgb: sum of Lr, w: copies
  vec4 sumSquares;  // rgb: sum of Lr^2, w: sum of rays
};
// After the table's cells, the same buffer holds one word per copies' cell: the key + 1 (earsCellKey) of a
// finest-level cell that hashes there, written by its training copies and by vertices that found the slot
// unresolved (0: none), so that the fold can find that cell's coarser levels.
VKMC_CONST uint kEarsCellWords = 8u;  // sizeof(EarsCell) / 4
VKMC_FN uint earsKeyWord(uint cell, uint tableCells) { return tableCells * kEarsCellWords + cell; }

// What the last fold resolved for a finest-level cell, as texels 2 cell and 2 cell + 1 of BINDING_EARS_SAMPLING
// (read with imageLoad: on lavapipe an inline gather, where a storage-buffer load loops over the lanes): its three
// levels' statistics shrunk coarsest first (earsShrunk), so that a vertex reads one cell, not three. Light cells
// alike, at the light cell beside it.
VKMC_CONST uint kEarsSamplingTexels = 2u;  // momentPerCost (rgb: E[Lr^2] / E[C], w: the most copies of any
                                           // level), variancePerCost (rgb: Var[Lr] / E[C], w: the cell's key + 1
                                           // as a float: exact below 2^24, and never a denormal)
// Whether a slot's resolved texels are those of `key`'s finest cell: keys that hash to one slot share its sums,
// but the fold resolves the coarser levels of one of them only (the key the slot's word holds); the others read
// nothing there (throughput roulette), as merged levels of another part of the scene misled their factors.
VKMC_FN bool earsResolvedFor(vec4 varianceTexel, uint key) { return varianceTexel.w == float(key + 1u); }

// One copy of a training vertex (slot * kEarsDepths + depth): where what its subtree gathers goes.
struct EarsRecord {
  vec4 gathered;  // rgb: minus the slot's gathered at the copy's start, plus what the slot and its children
                  // gathered; w: the same for rays
  vec4 scale;     // rgb: q / beta per channel (0 where beta is): the subtree's radiance into Lr; w: cell key + 1
                  // as float bits (earsCellKey; 0: no record)
};
// With ears_light_max > 0 each record has a light record, a vec4 after all the records in the same buffer
// (earsLightRecord): the copy's first light sample, rgb its v (kEarsLightUnoccluded), or while its shadow ray is
// pending the factor from its contribution to v (q qL / beta); w: kEarsLight*.
VKMC_CONST uint kEarsLightRecordBytes = 16u;

// A path slot's own sums for training, and where it was split off.
struct EarsSlot {
  vec4 gathered;    // rgb: radiance its paths added (their light samples included), w: rays they traced
  uint parent;      // slot + 1 of the path it was split from; 0: a camera path
  uint splitDepth;  // depth of the vertex that split it off (its records start there)
  uint unused0, unused1;
};

// A vertex's place in the cache: its cell of the finest grid (kEarsGridResolution along the scene's longest side,
// coordinates clamped to 7 bits) and its geometric normal's dominant signed axis, packed as x | y << 7 | z << 14 |
// bin << 21 (below 2^24: exact as a float). The cache holds kEarsLevels grids, each kEarsLevelShift bits coarser
// than the one before; the fold resolves a finest cell from its cells at every level (earsResolveLevel), as
// EARS's octree refines only cells with enough samples, and a vertex reads that one cell.
VKMC_FN uint earsCellKey(vec3 p, vec3 n, vec4 grid) {
  vec3 g = clamp(floor((p - vec3(grid)) * grid.w), vec3(0.0f), vec3(127.0f));
  vec3 a = abs(n);
  uint axis = a.x >= a.y && a.x >= a.z ? 0u : (a.y >= a.z ? 1u : 2u);
  float side = axis == 0u ? n.x : (axis == 1u ? n.y : n.z);
  uint bin = axis * 2u + (side < 0.0f ? 1u : 0u);
  return uint(g.x) | uint(g.y) << 7u | uint(g.z) << 14u | bin << 21u;
}

// The hash-table slot of a key's cell at `level` (0: the finest).
VKMC_FN uint earsCellIndex(uint key, uint level, uint cellMask) {
  uint shift = level * kEarsLevelShift;
  uint x = (key & 127u) >> shift, y = ((key >> 7u) & 127u) >> shift, z = ((key >> 14u) & 127u) >> shift;
  return hashU32(x * 0x8da6b343u ^ y * 0xd8163841u ^ z * 0xcb1ab31fu ^ (key >> 21u) * 0x9e3779b9u ^ level * 0x632be5abu) &
         cellMask;
}

// The light cell beside a copies' cell (the table's second half).
VKMC_FN uint earsLightCell(uint cell, uint cellMask) { return cell + cellMask + 1u; }

// A training copy's first shadow ray carries its slot and depth (EarsRecord index slot * kEarsDepths + depth).
VKMC_FN uint earsFirstLightTag(uint slot, uint depth) { return kEarsFirstLightTag | depth << kEarsTagDepthShift | slot; }
VKMC_FN uint earsTaggedRecord(uint tag) { return (tag & kEarsSlotMask) * kEarsDepths + ((tag >> kEarsTagDepthShift) & 3u); }

// EARS's factor (its recursive_path.cpp), t per channel: the second moment decides roulette, the variance
// splitting; where they disagree (the second moment says split, the variance roulette) the vertex stays as it is.
VKMC_FN float earsFactor(vec3 relativeThroughput, vec3 momentPerCost, vec3 variancePerCost, float imageFactor) {
  vec3 t2 = relativeThroughput * relativeThroughput;
  float byMoment = sqrt(dot(t2, momentPerCost) / 3.0f) * imageFactor;
  float byVariance = sqrt(dot(t2, variancePerCost) / 3.0f) * imageFactor;
  float q = byMoment > 1.0f ? max(byVariance, 1.0f) : byMoment;
  if (!(q >= 0.0f)) q = 1.0f;  // a cell whose sums overflowed (NaN): the vertex as it is
  return clamp(q, kEarsFactorMin, kEarsFactorMax);
}

// A cell's sampling statistics from its training sums (the fold between passes): momentPerCost, variancePerCost.
VKMC_FN void earsSampling(vec4 sum, vec4 sumSquares, INOUT(vec4) momentPerCost, INOUT(vec4) variancePerCost) {
  float n = sum.w;
  momentPerCost = vec4(0.0f);
  variancePerCost = vec4(0.0f);
  if (!(n > 0.0f)) return;
  vec3 mean = vec3(sum) / n, second = vec3(sumSquares) / n;
  float cost = sumSquares.w / n;
  momentPerCost.w = n;
  variancePerCost.w = cost;
  if (!(cost > 0.0f)) return;
  momentPerCost = vec4(second / cost, n);
  variancePerCost = vec4(max(second - mean * mean, vec3(0.0f)) / cost, cost);
}

// A level's learned statistic shrunk toward the coarser levels' (taken coarsest first) by how many copies it has
// learned from: a few hundred copies of a small cell rarely hold the rare bright paths that set its second
// moment, and a moment too small roulettes them (docs/journal/ears.md, 2026-11-29). The first level with copies is taken
// as it is.
VKMC_FN vec3 earsShrunk(vec3 coarser, float coarserCopies, vec3 level, float copies) {
  if (!(coarserCopies > 0.0f)) return level;
  return mix(coarser, level, copies / (copies + kEarsShrinkCopies));
}

// One level's cell sums mixed into the statistics resolved from the coarser levels before it (the fold, coarsest
// first): what a vertex in the finest cell reads.
VKMC_FN void earsResolveLevel(vec4 sum, vec4 sumSquares, INOUT(vec3) moment, INOUT(vec3) variance, INOUT(float) copies) {
  vec4 m, v;
  earsSampling(sum, sumSquares, m, v);
  if (!(m.w > 0.0f)) return;
  moment = earsShrunk(moment, copies, vec3(m), m.w);
  variance = earsShrunk(variance, copies, vec3(v), m.w);
  copies = copies > m.w ? copies : m.w;
}

// How many of a pass's samples per pixel train the cache: about kEarsTrainingPaths samples, at least one a
// pixel, at most the pass's. They run first, as a wavefront of their own (common.glsl earsTrains).
VKMC_FN uint earsTrainingSamples(uint pixels, uint samples) {
  uint perPixel = pixels >= kEarsTrainingPaths ? 1u : (kEarsTrainingPaths + pixels / 2u) / pixels;
  return perPixel < samples ? perPixel : samples;
}

// The histogram bin of a vertex's decision.
VKMC_FN uint earsBin(bool trained, float q) {
  return !trained ? kEarsBinFallback : (q < 1.0f ? kEarsBinRoulette : (q > 1.0f ? kEarsBinSplit : kEarsBinOne));
}

VKMC_END_NAMESPACE

#ifdef __cplusplus
namespace vkmc::gpu {
static_assert(sizeof(EarsHeader) == 48 + 2 * 4 * kEarsHistogramDepths * kEarsBins);
static_assert(sizeof(EarsCell) == 32 && sizeof(EarsRecord) == 32 && sizeof(EarsSlot) == 32);
static_assert(sizeof(EarsCell) == kEarsCellWords * 4);
static_assert(kEarsDepths <= 4u, "the first-light tag holds a depth in two bits");
}  // namespace vkmc::gpu
#endif
#endif
