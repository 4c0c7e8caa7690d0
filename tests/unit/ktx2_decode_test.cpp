// KTX2 textures (KHR_texture_basisu) through the vendored Basis Universal transcoder: ETC1S and UASTC (in
// Zstandard, with mips) decode to the texels they were encoded from; arrays, forged lengths, oversized and cut
// files are refused with a reason. The files in data/ktx2/ were written by basisu 1.16.4 from quadrants.png
// (data/ktx2/README.md).
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "error.h"
#include "scene/image_decode.h"
#include "scene/ktx2_decode.h"

using namespace vkmc;

namespace {

std::vector<unsigned char> readData(const std::string& name) {
  std::ifstream in(std::string(VKMC_SOURCE_DIR) + "/tests/unit/data/ktx2/" + name, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

DecodedImage decode(const std::vector<unsigned char>& bytes, uint32_t maxSide = 16384) {
  return decodeImage(bytes.data(), bytes.size(), maxSide, uint64_t(1) << 28);
}

std::string refusal(const std::vector<unsigned char>& bytes, uint32_t maxSide = 16384) {
  try {
    decode(bytes, maxSide);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

int largestDifference(const DecodedImage& a, const DecodedImage& b) {
  int largest = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) largest = std::max(largest, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
  return largest;
}

}  // namespace

// Four flat quadrants of known colours: each codec reproduces them, up to its quantisation (ETC1S keeps 5-bit
// endpoints; UASTC is near-lossless on flat blocks), the top row first as glTF and PNG have it.
TEST(Ktx2Decode, EachCodecDecodesToTheTexelsItWasEncodedFrom) {
  const DecodedImage source = decode(readData("quadrants.png"));
  for (const auto& [name, tolerance] : {std::pair{"quadrants_etc1s.ktx2", 8}, std::pair{"quadrants_uastc_zstd.ktx2", 2},
                                        std::pair{"quadrants_uastc_mips.ktx2", 2}}) {
    const std::vector<unsigned char> bytes = readData(name);
    ASSERT_TRUE(isKtx2(bytes.data(), bytes.size())) << name;
    const DecodedImage image = decode(bytes);
    ASSERT_EQ(image.width, 16u) << name;
    ASSERT_EQ(image.height, 16u) << name;
    EXPECT_LE(largestDifference(image, source), tolerance) << name << " (a flipped image differs by 170)";
  }
}

TEST(Ktx2Decode, AnArrayOfImagesIsRefused) {
  EXPECT_NE(refusal(readData("quadrants_array.ktx2")).find("a KTX2 array of 2 images"), std::string::npos);
}

TEST(Ktx2Decode, ASizePastTheLimitIsRefusedBeforeTranscoding) {
  EXPECT_NE(refusal(readData("quadrants_uastc_zstd.ktx2"), 8).find("16x16 exceeds 8 texels a side"), std::string::npos);
}

// The level index's uncompressed length sizes Zstandard's output: a forged one is refused, not allocated (the
// transcoder's own bound is 2 GiB).
TEST(Ktx2Decode, AForgedUncompressedLengthIsRefused) {
  std::vector<unsigned char> bytes = readData("quadrants_uastc_zstd.ktx2");
  const size_t uncompressedLength = 80 + 16;  // the 80-byte header, then level 0's byteOffset and byteLength
  const uint64_t forged = uint64_t(1) << 30;
  std::memcpy(bytes.data() + uncompressedLength, &forged, sizeof(forged));
  EXPECT_NE(refusal(bytes).find("declares 1073741824 bytes"), std::string::npos) << refusal(bytes);
}

// An ETC1S file that names Zstandard (the review's case): the transcoder would inflate its forged 2-GiB level before
// reading its format; it is refused from its header. A depth names a volume.
TEST(Ktx2Decode, ASchemeThatDoesNotFitTheDataAndAVolumeAreRefused) {
  std::vector<unsigned char> bytes = readData("quadrants_etc1s.ktx2");
  bytes[44] = 2;  // supercompressionScheme: Zstandard
  const uint64_t forged = 0x7FFFFFFF;
  std::memcpy(bytes.data() + 96, &forged, sizeof(forged));
  EXPECT_NE(refusal(bytes).find("ETC1S data in supercompression scheme 2"), std::string::npos) << refusal(bytes);
  std::vector<unsigned char> volume = readData("quadrants_uastc_zstd.ktx2");
  volume[28] = 4;  // pixelDepth
  EXPECT_NE(refusal(volume).find("a KTX2 volume"), std::string::npos) << refusal(volume);
}

// image_fuzzer's finding: a supercompression-data offset past 4 GiB, which the transcoder's 32-bit reading of the
// header wrapped into bounds and read 4 GiB before the file (tests/fuzz/regressions/images/).
TEST(Ktx2Decode, AnOffsetPastFourGibibytesIsRefusedNotWrapped) {
  std::ifstream in(std::string(VKMC_SOURCE_DIR) + "/tests/fuzz/regressions/images/ktx2_sgd_offset_wraps.ktx2", std::ios::binary);
  const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_GT(bytes.size(), 80u);
  EXPECT_NE(refusal(bytes).find("its supercompression data lies past the end of the file"), std::string::npos) << refusal(bytes);
}

// image_fuzzer's second finding: an ETC1S file whose Huffman table made the transcoder's tree read past its end
// (third_party/basisu/README.md). Mended in place, it decodes or is refused, and under ASan reads nothing outside.
TEST(Ktx2Decode, AHuffmanTableOfOneLongCodeReadsInsideItsTree) {
  std::ifstream in(std::string(VKMC_SOURCE_DIR) + "/tests/fuzz/regressions/images/ktx2_huffman_tree_sibling.ktx2",
                   std::ios::binary);
  const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_GT(bytes.size(), 80u);
  try {
    const DecodedImage image = decode(bytes);
    EXPECT_EQ(image.rgba.size(), size_t(image.width) * image.height * 4);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("KTX2"), std::string::npos) << e.what();
  }
}

// Every cut of each file is refused with a reason (the identifier alone is not a KTX2), and every single flipped
// byte either decodes to an image of the declared size or is refused: no crash, no hang.
TEST(Ktx2Decode, CutOrDamagedFilesAreRefusedOrDecodedNeverCrash) {
  for (const char* name : {"quadrants_etc1s.ktx2", "quadrants_uastc_zstd.ktx2"}) {
    const std::vector<unsigned char> bytes = readData(name);
    for (size_t cut = 12; cut < bytes.size(); ++cut)
      EXPECT_FALSE(refusal(std::vector<unsigned char>(bytes.begin(), bytes.begin() + cut)).empty()) << name << " cut at " << cut;
    for (size_t at = 12; at < bytes.size(); ++at) {
      std::vector<unsigned char> damaged = bytes;
      damaged[at] ^= 0x5A;
      try {
        const DecodedImage image = decode(damaged);
        EXPECT_EQ(image.rgba.size(), size_t(image.width) * image.height * 4) << name << " damaged at " << at;
      } catch (const Error&) {
      }
    }
  }
}
