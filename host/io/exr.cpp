// EXR through OpenEXR's C++ API (float channels, ZIP compression).
#include "io/exr.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "error.h"
#include "io/exr_header_check.h"
#include "io/output_files.h"

namespace vkmc {

std::string encodeExr(const ExrImage& image) {
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer fb;
    for (const auto& [name, data] : image.channels) {
      if (data.size() != static_cast<size_t>(image.width) * image.height)
        throw Error("EXR channel " + name + " has the wrong size");
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      fb.insert(name, Imf::Slice(Imf::FLOAT, (char*)data.data(), sizeof(float), sizeof(float) * image.width));
    }
    Imf::StdOSStream stream;
    {
      Imf::OutputFile file(stream, header);
      file.setFrameBuffer(fb);
      file.writePixels(image.height);
    }
    return stream.str();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(std::string("cannot encode EXR: ") + e.what());
  }
}

void writeExr(const std::string& path, const ExrImage& image) { writeFileAtomically(path, encodeExr(image)); }

ExrImage filmToImage(const Film& film) {
  ExrImage img;
  img.width = static_cast<int>(film.width);
  img.height = static_cast<int>(film.height);
  const char* rgb[] = {"R", "G", "B"};
  const char* var[] = {"variance.R", "variance.G", "variance.B"};
  for (int c = 0; c < 3; ++c) {
    auto& m = img.channels[rgb[c]];
    m.resize(film.pixels());
    for (size_t p = 0; p < film.pixels(); ++p) m[p] = static_cast<float>(film.mean(p, c));
  }
  auto& s = img.channels["samples"];
  s.resize(film.pixels());
  for (size_t p = 0; p < film.pixels(); ++p) s[p] = static_cast<float>(film.count[p]);
  auto& cost = img.channels["cost"];
  cost.resize(film.pixels());
  for (size_t p = 0; p < film.pixels(); ++p) cost[p] = static_cast<float>(film.cost(p));
  // No variance channels where the film estimates none (one scrambling a pixel): a 0 would read as certainty.
  if (!film.estimatesVariance()) return img;
  for (int c = 0; c < 3; ++c) {
    auto& v = img.channels[var[c]];
    v.resize(film.pixels());
    for (size_t p = 0; p < film.pixels(); ++p) v[p] = static_cast<float>(film.varianceOfMean(p, c));
  }
  auto& dof = img.channels["variance.dof"];
  dof.resize(film.pixels());
  for (size_t p = 0; p < film.pixels(); ++p) dof[p] = static_cast<float>(film.varianceDof(p));
  auto& efficiency = img.channels["efficiency"];
  efficiency.resize(film.pixels());
  for (size_t p = 0; p < film.pixels(); ++p) efficiency[p] = static_cast<float>(std::min(film.efficiency(p), 3.0e38));
  return img;
}

void writeFilmExr(const std::string& path, const Film& film) { writeExr(path, filmToImage(film)); }
std::string encodeFilmExr(const Film& film) { return encodeExr(filmToImage(film)); }

ExrImage decodeExr(const std::string& bytes, const std::string& name, uint64_t maxValues) {
  checkExrHeaders(bytes, name, maxValues);
  try {
    Imf::StdISStream stream;
    stream.str(bytes);
    Imf::InputFile file(stream);
    Imath::Box2i dw = file.header().dataWindow();
    ExrImage img;
    // In 64 bits: a forged window's sides overflow int, and its size must be refused before anything is allocated.
    const int64_t width = int64_t(dw.max.x) - dw.min.x + 1, height = int64_t(dw.max.y) - dw.min.y + 1;
    uint64_t channels = 0;
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) ++channels;
    checkExrDeclaredSize(width, height, channels, maxValues, name);  // again, as OpenEXR read it
    img.width = int(width);
    img.height = int(height);
    Imf::FrameBuffer fb;
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
      auto& data = img.channels[it.name()];
      data.resize(static_cast<size_t>(img.width) * img.height);
      char* base = (char*)(data.data() - dw.min.x - static_cast<ptrdiff_t>(dw.min.y) * img.width);
      fb.insert(it.name(), Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * img.width));
    }
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return img;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error("cannot read EXR '" + name + "': " + e.what());
  }
}

ExrImage readExr(const std::string& path, uint64_t maxValues) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error("cannot read EXR '" + path + "': " + (std::filesystem::exists(path, ec) ? "not a regular file" : "no such file"));
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw Error("cannot read EXR '" + path + "'");
  return decodeExr(bytes, path, maxValues);
}

}  // namespace vkmc
