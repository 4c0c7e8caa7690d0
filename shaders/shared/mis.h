// Multiple importance sampling weights (Veach 1997) as pure functions of the two techniques' pdfs.
#ifndef VKMC_MIS_H
#define VKMC_MIS_H
#include "glsl_cpp.h"
#include "layout.h"
VKMC_BEGIN_NAMESPACE

VKMC_FN float balanceHeuristic(float pdfA, float pdfB) { return pdfA + pdfB > 0.0f ? pdfA / (pdfA + pdfB) : 0.0f; }

VKMC_FN float powerHeuristic(float pdfA, float pdfB) {
  float a = pdfA * pdfA;
  float b = pdfB * pdfB;
  return a + b > 0.0f ? a / (a + b) : 0.0f;
}

// The weight of a sample of technique A (pdfThis) against technique B (pdfOther) under heuristic kMis*; kMisNone
// weighs every sample 1 (the caller then counts a path by one technique only).
VKMC_FN float misWeight(uint heuristic, float pdfThis, float pdfOther) {
  if (heuristic == kMisBalance) return balanceHeuristic(pdfThis, pdfOther);
  if (heuristic == kMisPower) return powerHeuristic(pdfThis, pdfOther);
  return 1.0f;
}

VKMC_END_NAMESPACE
#endif
