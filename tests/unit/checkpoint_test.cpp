// Checkpoint files (io/checkpoint.h): what is written is read back exactly, and anything that is not a whole,
// intact checkpoint is refused with a line naming the file and the problem.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "error.h"
#include "io/checkpoint.h"
#include "scene/content_hash.h"

using namespace vkmc;

namespace {

Checkpoint sample(bool withBatch) {
  Checkpoint c;
  c.config = {{"options", {{"spp", 64}}}, {"scene_fingerprint", "0123456789abcdef"}};
  RenderState& s = c.state;
  s.film = Film(3, 2);
  s.film.replicateVariance = true;
  s.film.replicates = 3;
  for (size_t i = 0; i < s.film.sum.size(); ++i)
    s.film.sum[i] = 0.1 * double(i) + 1e-17, s.film.sumSq[i] = std::ldexp(1.0, int(i) * 50);
  for (size_t i = 0; i < s.film.count.size(); ++i) s.film.count[i] = 1000 + i, s.film.nonfinite[i] = i;
  for (size_t i = 0; i < s.film.replicateSum.size(); ++i) s.film.replicateSum[i] = -double(i) / 3.0;
  for (size_t i = 0; i < s.film.replicateCount.size(); ++i) s.film.replicateCount[i] = 250 + i;
  s.nextSample = 40;
  if (withBatch) {
    s.batchSamples = 8;
    s.batch.resize(s.film.pixels());
    for (size_t p = 0; p < s.batch.size(); ++p) s.batch[p].sum[0] = float(p) + 0.5f, s.batch[p].replicate[2][3] = 2.0f;
  }
  s.stats.seconds = 1.25;
  s.stats.cameraRays = 1ull << 40;
  s.stats.stageSeconds["shade"] = 0.5;
  s.stats.stagesUntimed = true;  // a part without stage timestamps: a resumed report must not call the stages whole
  s.stats.gpuSeconds = 0.75;
  s.stats.pathsByBounce = {7, 8, 9};
  return c;
}

std::string refusal(const std::string& bytes) {
  try {
    decodeCheckpoint(bytes, "ck.bin");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Checkpoint, RoundTripsEveryArrayAndCounterExactly) {
  for (bool withBatch : {false, true}) {
    const Checkpoint c = sample(withBatch);
    const Checkpoint d = decodeCheckpoint(encodeCheckpoint(c), "ck.bin");
    EXPECT_EQ(d.config, c.config);
    EXPECT_EQ(d.state.film.width, 3u);
    EXPECT_EQ(d.state.film.height, 2u);
    EXPECT_TRUE(d.state.film.replicateVariance);
    EXPECT_EQ(d.state.film.replicates, 3u);
    EXPECT_EQ(d.state.film.sum, c.state.film.sum);
    EXPECT_EQ(d.state.film.sumSq, c.state.film.sumSq);
    EXPECT_EQ(d.state.film.count, c.state.film.count);
    EXPECT_EQ(d.state.film.nonfinite, c.state.film.nonfinite);
    EXPECT_EQ(d.state.film.replicateSum, c.state.film.replicateSum);
    EXPECT_EQ(d.state.film.replicateCount, c.state.film.replicateCount);
    EXPECT_EQ(d.state.nextSample, 40u);
    EXPECT_EQ(d.state.batchSamples, c.state.batchSamples);
    ASSERT_EQ(d.state.batch.size(), c.state.batch.size());
    if (withBatch) {
      EXPECT_EQ(std::memcmp(d.state.batch.data(), c.state.batch.data(), c.state.batch.size() * sizeof(gpu::FilmPixel)), 0);
    }
    EXPECT_EQ(d.state.stats.seconds, 1.25);
    EXPECT_EQ(d.state.stats.cameraRays, 1ull << 40);
    EXPECT_EQ(d.state.stats.stageSeconds.at("shade"), 0.5);
    EXPECT_TRUE(d.state.stats.stagesUntimed);
    EXPECT_EQ(d.state.stats.gpuSeconds, 0.75);
    EXPECT_EQ(d.state.stats.pathsByBounce, (std::vector<uint64_t>{7, 8, 9}));
  }
}

TEST(Checkpoint, TheImageOfAStateAddsItsUnfoldedBatch) {
  const Checkpoint c = sample(true);
  Film image = c.state.image();
  EXPECT_DOUBLE_EQ(image.sum[3 * 2], c.state.film.sum[3 * 2] + 2.5);
  EXPECT_DOUBLE_EQ(image.sum[1], c.state.film.sum[1]);
}

TEST(Checkpoint, EveryCorruptionIsRefusedWithOneReason) {
  const std::string good = encodeCheckpoint(sample(true));
  EXPECT_NE(refusal("").find("is not a vkmc checkpoint"), std::string::npos);
  EXPECT_NE(refusal("P6 3 2 255\n").find("is not a vkmc checkpoint"), std::string::npos);
  for (size_t cut : {size_t(17), size_t(30), good.size() / 2, good.size() - 1})
    EXPECT_NE(refusal(good.substr(0, cut)).find("is truncated"), std::string::npos) << cut;
  EXPECT_NE(refusal(good + "x").find("after its end"), std::string::npos);
  // One flipped bit anywhere after the magic: the header, the film, the batch or the checksum itself.
  for (size_t at : {size_t(30), good.size() / 2, good.size() - 40, good.size() - 3}) {
    std::string bad = good;
    bad[at] ^= 0x10;
    std::string why = refusal(bad);
    EXPECT_TRUE(why.find("corrupt") != std::string::npos || why.find("truncated") != std::string::npos) << at << ": " << why;
    EXPECT_NE(why.find("'ck.bin'"), std::string::npos) << why;
  }
}

namespace {

// A checkpoint file around `header` and `payload` with a valid checksum: what a forger (or a bug) could write.
std::string sealed(const std::string& header, const std::string& payload) {
  auto u64 = [](uint64_t v) { return std::string(reinterpret_cast<const char*>(&v), 8); };
  std::string bytes = "VKMC-CHECKPOINT\n" + u64(header.size()) + header + u64(payload.size()) + payload;
  ContentHash h;
  h.add(bytes.data(), bytes.size());
  return bytes + u64(h.value());
}

// The header and payload of an encoded checkpoint.
std::pair<nlohmann::json, std::string> opened(const std::string& bytes) {
  uint64_t headerBytes, payloadBytes;
  std::memcpy(&headerBytes, bytes.data() + 16, 8);
  std::memcpy(&payloadBytes, bytes.data() + 24 + headerBytes, 8);
  return {nlohmann::json::parse(bytes.substr(24, headerBytes)), bytes.substr(32 + headerBytes, payloadBytes)};
}

}  // namespace

// Sealed with a valid checksum but absurd: an image of 16384 x 16384 over a few bytes of film is refused before its
// film is allocated (the child runs under a 1 GiB address-space cap, where that film would not fit), and sample
// counts no render reaches are refused instead of reported.
TEST(Checkpoint, AbsurdHeadersAreRefusedBeforeAllocation) {
  auto [header, payload] = opened(encodeCheckpoint(sample(true)));
  nlohmann::json huge = header;
  huge["width"] = 16384, huge["height"] = 16384;
  const std::string forged = sealed(huge.dump(), payload);
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    rlimit cap{uint64_t(1) << 30, uint64_t(1) << 30};
    setrlimit(RLIMIT_AS, &cap);
    _exit(refusal(forged).find("of film where its image needs") != std::string::npos ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  nlohmann::json spp = header;
  spp["next_sample"] = 4294967295u;
  EXPECT_NE(refusal(sealed(spp.dump(), payload)).find("has an impossible next_sample"), std::string::npos);
  nlohmann::json claims = header;
  claims["stats"]["samples_per_pixel"] = 1000;  // more than the 40 samples its next sample says were done
  EXPECT_NE(refusal(sealed(claims.dump(), payload)).find("sample counts no render reaches"), std::string::npos);
  nlohmann::json odd = header;
  odd["format"] = {{"not", "a string"}};  // found by checkpoint_fuzzer: a JSON type error escaped as an exception
  EXPECT_NE(refusal(sealed(odd.dump(), payload)).find("is not a vkmc checkpoint"), std::string::npos);
  nlohmann::json floaty = header;
  floaty["width"] = 1e300;  // a float never converts to a count (an undefined conversion before)
  EXPECT_NE(refusal(sealed(floaty.dump(), payload)).find("has an impossible width"), std::string::npos);
  EXPECT_EQ(refusal(sealed(header.dump(), payload)), "") << "the reseal itself is valid";
  // A config nested 100,000 deep: refused by a scan that keeps nothing (copying or dumping it would recurse that
  // deep and overflow the stack).
  nlohmann::json marked = header;
  marked["config"]["deep"] = "DEEP";
  std::string deep = marked.dump();
  deep.replace(deep.find("\"DEEP\""), 6, std::string(100000, '[') + std::string(100000, ']'));
  EXPECT_NE(refusal(sealed(deep, payload)).find("nested deeper than"), std::string::npos);
}

// A file larger than any image's checkpoint is refused from its size, before a byte is read (a sparse file: it
// takes no disk).
TEST(Checkpoint, AFileLargerThanAnyCheckpointIsRefusedUnread) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("vkmc_huge_checkpoint_" + std::to_string(getpid()));
  { std::ofstream(path, std::ios::binary) << "VKMC-CHECKPOINT\n"; }
  std::filesystem::resize_file(path, largestCheckpointBytes() + 1);
  std::string error;
  try {
    readCheckpoint(path.string());
  } catch (const Error& e) {
    error = e.what();
  }
  std::filesystem::remove(path);
  EXPECT_NE(error.find("more than any image's checkpoint"), std::string::npos) << error;
}
