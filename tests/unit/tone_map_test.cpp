// The PNG preview's look (io/tone_map.h): Reinhard's automatic exposure, the Khronos PBR Neutral tone map, the
// flags' parsing.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "error.h"
#include "io/png.h"
#include "io/tone_map.h"

using namespace vkmc;

TEST(ToneMap, AutomaticExposureBringsTheLogAverageToMiddleGrey) {
  for (double level : {1e-5, 0.01, 1.0, 2534.0}) {
    const std::vector<double> constant(100, level);
    EXPECT_NEAR(autoExposureStops(constant), std::log2(kMiddleGrey / level), 1e-5) << level;
  }
  // Half the pixels at 4, half at 1: the log-average is 2 (the geometric mean), not the arithmetic 2.5.
  std::vector<double> two(50, 4.0);
  two.insert(two.end(), 50, 1.0);
  EXPECT_NEAR(autoExposureStops(two), std::log2(kMiddleGrey / 2.0), 1e-5);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_NEAR(autoExposureStops({1.0, nan, inf, -1.0}), std::log2(kMiddleGrey), 1e-5) << "non-finite and negative ignored";
  EXPECT_EQ(autoExposureStops({0.0, 0.0}), 0.0) << "a black image is not scaled";
  // A subject against a black world: exposed for the subject, not for the mostly black frame.
  std::vector<double> subject(90, 0.0);
  subject.insert(subject.end(), 10, 0.3);
  EXPECT_NEAR(autoExposureStops(subject), std::log2(kMiddleGrey / 0.3), 1e-9);
  EXPECT_EQ(autoExposureStops({1e-300}), kMaxAutoStops) << "bounded";
}

TEST(ToneMap, AutomaticExposureKeepsTheScenesHighlights) {
  // A backdrop of grey 0.18 over 80% of the image and a board at 100 over the rest (a bright sun): the log-average
  // key alone would put the board at 100 x 2^-2.5, white. The highlights rule lowers it until the board's 90th
  // percentile is at kHighlightLimit.
  std::vector<double> image(80, 0.18), scene(20, 100.0);
  image.insert(image.end(), scene.begin(), scene.end());
  const PreviewLook autoLook;
  EXPECT_LT(highlightStops(scene), autoExposureStops(image));
  EXPECT_NEAR(exposureFor(autoLook, image, scene), std::log2(kHighlightLimit / 100.0), 1e-9);
  // A model lit as the studio lights it keeps the whole image's key: its highlights are below the limit.
  std::vector<double> model(20, 0.6);
  std::vector<double> studio(80, 0.18);
  studio.insert(studio.end(), model.begin(), model.end());
  EXPECT_EQ(exposureFor(autoLook, studio, model), autoExposureStops(studio));
  // Only a tenth of the scene's pixels may pass it: a specular glint on 5% of them does not darken the image.
  std::vector<double> glints(95, 0.6);
  glints.insert(glints.end(), 5, 1e4);
  EXPECT_NEAR(highlightStops(glints), std::log2(kHighlightLimit / 0.6), 1e-9);
  EXPECT_EQ(highlightStops({}), kMaxAutoStops) << "nothing but backdrop: no highlight to keep";
  EXPECT_EQ(exposureFor(PreviewLook{ToneMap::Neutral, 1.5}, image, scene), 1.5) << "fixed stops are kept as given";
}

TEST(ToneMap, APixelOfOnlyBackdropIsToldApartDespiteTheDevicesFloatSums) {
  // Pixel 0: 32 samples of the backdrop's grey summed in float, as a device batch sums them (its variance of the
  // mean is not 0 but about 1.6e-8 b^2, from the sum of squares' rounding); pixel 1: a lamp at 50 +- 10.
  const float b = 0.18f;
  Film film(2, 1);
  film.replicateVariance = false;
  float sum = 0.0f, sumSq = 0.0f;
  for (int i = 0; i < 32; ++i) sum += b, sumSq += b * b;
  for (int c = 0; c < 3; ++c) {
    film.sum[c] = sum, film.sumSq[c] = sumSq;
    film.sum[3 + c] = 32 * 50.0, film.sumSq[3 + c] = 16 * (40.0 * 40.0 + 60.0 * 60.0);
  }
  film.count = {32, 32};
  ASSERT_GT(film.varianceOfMean(0, 0), 1e-10 * b * b) << "the rounding the tolerance must allow for";
  FilmPreview preview = encodeFilmPng(film, PreviewLook{}, b);
  EXPECT_EQ(preview.backdropShare, 0.5);
  EXPECT_NEAR(preview.stops, std::log2(kHighlightLimit / 50.0), 1e-9) << "the lamp's highlights kept";
  // Without a backdrop there are no scene pixels to tell apart: the whole image's key, sqrt(0.18 x 50) = 3.
  preview = encodeFilmPng(film, PreviewLook{}, 0.0f);
  EXPECT_EQ(preview.backdropShare, 0.0);
  EXPECT_NEAR(preview.stops, std::log2(kMiddleGrey / 3.0), 1e-6) << "to the float grey's rounding";
}

TEST(ToneMap, PbrNeutralFollowsTheKhronosReference) {
  // Grey 1 by the reference's formula: offset 0.04, peak 0.96, new peak 1 - 0.24^2 / 0.44.
  const double expected = 1.0 - 0.24 * 0.24 / 0.44;
  for (double c : pbrNeutral({1.0, 1.0, 1.0})) EXPECT_NEAR(c, expected, 1e-12);
  for (double c : pbrNeutral({0.5, 0.5, 0.5})) EXPECT_NEAR(c, 0.46, 1e-12) << "below the knee: the offset only";
  double previous = -1.0;
  for (double v = 0.0; v < 1e4; v = v * 1.1 + 1e-3) {
    const std::array<double, 3> out = pbrNeutral({v, 0.5 * v, 0.25 * v});
    EXPECT_GE(out[0], previous - 1e-12) << "monotone at " << v;
    EXPECT_LE(out[0], 1.0) << v;
    EXPECT_GE(out[2], 0.0) << v;
    previous = out[0];
  }
}

TEST(ToneMap, PreviewPixelsAreSrgbAfterExposureAndToneMap) {
  EXPECT_EQ(previewPixel({0.25, 0.25, 0.25}, 2.0, ToneMap::Clamp), (std::array<uint8_t, 3>{255, 255, 255}));
  EXPECT_EQ(previewPixel({0.5, 0.0, std::nan("")}, 0.0, ToneMap::Clamp), (std::array<uint8_t, 3>{toSrgb8(0.5), 0, 0}));
  EXPECT_LT(previewPixel({4.0, 4.0, 4.0}, 0.0, ToneMap::Neutral)[0], 255) << "four times white: compressed, not clipped";
}

TEST(ToneMap, FlagsAreParsedOrRefusedWithOneLine) {
  EXPECT_FALSE(parseExposure("auto").has_value());
  EXPECT_EQ(parseExposure("-2.5"), -2.5);
  for (const char* bad : {"nan", "inf", "101", "", "2 stops", "bright"}) EXPECT_THROW(parseExposure(bad), Error) << bad;
  EXPECT_EQ(parseToneMap("neutral"), ToneMap::Neutral);
  EXPECT_EQ(parseToneMap("clamp"), ToneMap::Clamp);
  EXPECT_THROW(parseToneMap("aces"), Error);
}
