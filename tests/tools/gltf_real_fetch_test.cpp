// tools/gltf_real_fetch.py on a small repository made here: each listed file is laid out as it was at the listed
// commit (not the clone's head), a .gltf with its external buffer and image (a URI with an escaped space, in a
// folder) and without its data: URI, a .glb with the image it names beside it, and a repository the list names but
// CLONES_DIR lacks is named, with exit 1.
#include <gtest/gtest.h>

#include <fstream>

#include "support/cli_run.h"

namespace fs = std::filesystem;
using namespace vkmc::test;

namespace {

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// A .glb whose JSON chunk names one image file by URI (no binary chunk).
std::string glbNaming(const std::string& uri) {
  std::string json = R"({"asset":{"version":"2.0"},"images":[{"uri":")" + uri + R"("}]})";
  while (json.size() % 4) json += ' ';
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  return "glTF" + u32(2) + u32(uint32_t(20 + json.size())) + u32(uint32_t(json.size())) + "JSON" + json;
}

std::string git(const fs::path& repo, const std::string& args) {
  return "git -C '" + repo.string() + "' -c user.name=t -c user.email=t@t " + args;
}

}  // namespace

TEST(GltfRealFetch, LaysOutTheListedCommitsFilesWithTheirBuffersAndImages) {
  if (runShell("command -v git && command -v python3").code != 0) GTEST_SKIP() << "needs git and python3";
  const fs::path dir = workDir() / "gltf_real_fetch";
  fs::remove_all(dir);
  const fs::path repo = dir / "clones" / "someone__models";
  const std::string gltf =
      R"({"asset":{"version":"2.0"},"buffers":[{"uri":"buf%20one.bin","byteLength":4},)"
      R"({"uri":"data:application/octet-stream;base64,AAAA","byteLength":3}],"images":[{"uri":"maps/tex.png"}]})";
  write(repo / "room" / "room.gltf", gltf);
  write(repo / "room" / "buf one.bin", "BIN1");
  write(repo / "room" / "maps" / "tex.png", "PNG1");
  write(repo / "props" / "chair.glb", "glTF-first");
  write(repo / "kit" / "crate.glb", glbNaming("Textures/atlas.png"));
  write(repo / "kit" / "Textures" / "atlas.png", "PNG2");
  ASSERT_EQ(runShell("git init -q '" + repo.string() + "' && " + git(repo, "add -A") + " && " + git(repo, "commit -qm one")).code,
            0);
  const std::string commit = runShell(git(repo, "rev-parse HEAD")).out.substr(0, 40);
  write(repo / "props" / "chair.glb", "glTF-second");  // the head differs from the listed commit
  ASSERT_EQ(runShell(git(repo, "commit -qam two")).code, 0);

  const fs::path list = dir / "list.txt";
  write(list,
        "# name | path | source | license | features\n"
        "room | someone__models/room/room.gltf | someone/models@" +
            commit +
            " | MIT | test\n"
            "chair | someone__models/props/chair.glb | someone/models@" +
            commit +
            " | MIT | test\n"
            "crate | someone__models/kit/crate.glb | someone/models@" +
            commit + " | MIT | test\n");
  const std::string tool = "python3 " + std::string(VKMC_SOURCE_DIR) + "/tools/gltf_real_fetch.py '" + (dir / "clones").string() +
                           "' '" + (dir / "models").string() + "' --list '";
  RunResult r = runShell(tool + list.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const fs::path models = dir / "models" / "someone__models";
  EXPECT_EQ(slurp(models / "room" / "room.gltf"), gltf);
  EXPECT_EQ(slurp(models / "room" / "buf one.bin"), "BIN1");
  EXPECT_EQ(slurp(models / "room" / "maps" / "tex.png"), "PNG1");
  EXPECT_EQ(slurp(models / "props" / "chair.glb"), "glTF-first") << "the listed commit's file, not the head's";
  EXPECT_EQ(slurp(models / "kit" / "Textures" / "atlas.png"), "PNG2") << "a .glb's external image, as Kenney's kits name";

  write(list, "gone | elsewhere__absent/a.glb | elsewhere/absent@" + commit + " | MIT | test\n");
  r = runShell(tool + list.string() + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("no clone of elsewhere/absent"), std::string::npos) << r.err;
}
