#include "fuzz_targets.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "builtin/builtin_plugins.h"
#include "core/error.h"
#include "core/number_text.h"
#include "core/transform.h"
#include "distribute/manifest.h"
#include "distribute/merge.h"
#include "emitters/envmap_emitter.h"
#include "fit/spectra_fit.h"
#include "integrators/volume_transport.h"
#include "io/feather_ply.h"
#include "io/image.h"
#include "io/image_file_reader.h"
#include "io/volume_grid_file.h"
#include "media/const_volume.h"
#include "media/grid_volume.h"
#include "media/heterogeneous_medium.h"
#include "media/isotropic_phase.h"
#include "media/tabulated_phase.h"
#include "optics/film_layer_text.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "shapes/feather_shape.h"
#include "shapes/obj_mesh.h"
#include "shapes/ply_mesh.h"
#include "shapes/sdf_grid_shape.h"
#include "shapes/serialized_mesh.h"
#include "shapes/triangle_mesh.h"
#include "textures/bitmap_texture.h"
#include "vision/observer_definition_file.h"
#include "vision/observer_table.h"

namespace columba::fuzz {

namespace {
// Every curve of an observer finite, non-negative and of area 1, as a reader promises.
void checkObserverCurves(const Observer& o) {
  auto check = [&](const std::vector<float>& curve, const std::string& channel) {
    double area = 0.0;
    for (float v : curve) {
      if (!(v >= 0.0f && std::isfinite(v)))
        throw std::logic_error("channel " + channel + " has a sensitivity of " + std::to_string(v));
      area += double(v) * o.grid.stepNm;
    }
    if (!(std::abs(area - 1.0) < 1e-3))
      throw std::logic_error("channel " + channel + " has area " + std::to_string(area));
  };
  for (size_t c = 0; c < o.channels.size(); ++c) check(o.sensitivities[c], o.channels[c]);
  if (o.hasAchromatic()) check(o.achromatic, o.achromaticChannel);
}

// An environment map of `image` and a few lookups and samples.
void lookUpEnvmap(Image image, const std::string& path) {
  EnvmapEmitter envmap(std::move(image), 1.0f, Transform(), {path, 0});
  Wavelengths wl = Wavelengths::sample(0.5f, WavelengthDensity::RGBMatching);
  for (const Vec3& d : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0.3f, 0.2f, -0.93f)}) {
    (void)envmap.radianceFromDirection(d, wl);
    (void)envmap.pdfDirection(d);
  }
  (void)envmap.sample(Vec3(0, 0, 0), Vec2(0.25f, 0.75f), wl);
}

// Runs `read`, reporting the std::runtime_error it rejects bad input with as an InputError.
template <class Read>
void rejectingWithInputError(Read read) {
  try {
    read();
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError({}, e.what());
  }
}

// Part 2 of 2 of a 16 x 16 render, written once, for fuzzed pieces to be merged with.
const Piece& fuzzPart2() {
  static const Piece piece = [] {
    PieceInfo info;
    info.scene = "fuzz.xml";
    info.sceneHash = textHash("fuzz");
    info.spp = 4;
    info.frameWidth = info.frameHeight = 16;
    info.part = PieceIndex{2, 2};
    info.partBounds = {0, 8, 16};
    const PixelRect window{0, 8, 16, 16};
    Image image(window.width(), window.height());
    std::fill(image.rgb.begin(), image.rgb.end(), 0.5f);
    const std::string path = writeScratchFile(nullptr, 0, ".part2of2.exr");
    writeEXRWindow(path, image, window, 16, 16, pieceMetadata(info));
    return loadPiece(path);
  }();
  return piece;
}
}  // namespace

std::string writeScratchFile(const uint8_t* data, size_t size, const std::string& suffix) {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d = std::filesystem::temp_directory_path() / ("columba-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  std::string path = (dir / ("input" + suffix)).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  out.close();
  if (!out) throw std::runtime_error("cannot write the scratch file " + path);
  return path;
}

void sceneFromBytes(const uint8_t* data, size_t size, const std::string& baseDir) {
  std::string text(reinterpret_cast<const char*>(data), size);
  Defines defines;
  size_t pos = 0;
  while (text.compare(pos, 2, "-D") == 0) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string define = text.substr(pos + 2, end - pos - 2);
    size_t eq = define.find('=');
    if (eq != std::string::npos) defines[define.substr(0, eq)] = define.substr(eq + 1);
    pos = end < text.size() ? end + 1 : end;
  }
  ParsedScene parsed;
  try {
    parsed = loadSceneString(text.substr(pos), "<fuzz>", baseDir, defines, builtinPlugins());
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    // A malformed -D name is the command line's error, which the loader reports as such.
    if (std::string(e.what()).rfind("-D ", 0) == 0) throw InputError({"<command line>", 0}, e.what());
    throw;
  }
  Scene scene(parsed, {"<fuzz>", 0});
}

void plyMeshFromBytes(const uint8_t* data, size_t size) {
  std::string path = writeScratchFile(data, size, ".ply");
  TriangleMesh mesh(readPlyMesh(path), Transform(), false, false, {path, 0});
}

void featherPlyFromBytes(const uint8_t* data, size_t size) {
  std::string path = writeScratchFile(data, size, ".ply");
  FeatherPlyData ply = readFeatherPly(path);
  FeatherShapeParams params;
  if (ply.barbWidth) params.barbWidth = *ply.barbWidth;
  FeatherShape shape(std::move(ply), params);
}

void objMeshFromBytes(const uint8_t* data, size_t size) {
  std::string path = writeScratchFile(data, size, ".obj");
  TriangleMesh mesh(readObjMesh(path), Transform(), false, false, {path, 0});
}

void serializedMeshFromBytes(const uint8_t* data, size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  for (int index : {0, 1}) {
    SerializedMesh s = parseSerializedMesh(bytes, index, "<fuzz>");
    TriangleMesh mesh(std::move(s.mesh), Transform(), s.faceNormals, false, {"<fuzz>", 0});
  }
}

void sdfGridFromBytes(const uint8_t* data, size_t size) {
  SDFGridShape shape(parseVolumeGrid(std::string(reinterpret_cast<const char*>(data), size), "<fuzz>"),
                     Transform::scale(Vec3(2, 1, 0.5f)), SDFGridShape::Normals::Smooth, false, "<fuzz>");
  const Vec3 origins[] = {Vec3(-1, 0.3f, 0.2f), Vec3(1, 0.5f, 0.25f), Vec3(3, 2, 1)};
  for (unsigned voxel = 0; voxel < std::min<size_t>(shape.primitiveCount(), 64); ++voxel) {
    Vec3 lo, hi;
    shape.primitiveBounds(voxel, lo, hi);
    for (const Vec3& o : origins) {
      const Vec3 d = normalize(shape.toWorldPoint((lo + hi) * 0.5f) - o);
      float t;
      if (shape.intersectPrimitive(voxel, o, d, 0.0f, INFINITY, t)) (void)shape.primitiveNormal(voxel, o + d * t);
    }
  }
}

void exrEnvmapFromBytes(const uint8_t* data, size_t size) {
  std::string path = writeScratchFile(data, size, ".exr");
  lookUpEnvmap(readEXR(path), path);
}

void hdrEnvmapFromBytes(const uint8_t* data, size_t size) {
  std::string path = writeScratchFile(data, size, ".hdr");
  lookUpEnvmap(readLinearRGBImage(path), path);
}

void bitmapFromBytes(const uint8_t* data, size_t size) {
  std::string path = writeScratchFile(data, size, ".img");
  (void)readImagePixels(path, true);
  // Raw: fitting every texel's colour to a spectrum is the texture's work, not the reader's, and
  // slows the fuzzer a hundredfold.
  BitmapTexture texture(readImagePixels(path, false), true, TextureFilter::Bilinear, TextureWrap::Mirror, Transform());
  Wavelengths wl = Wavelengths::sample(0.5f, WavelengthDensity::RGBMatching);
  for (const Vec2& uv : {Vec2(0.1f, 0.2f), Vec2(0.9f, 0.6f), Vec2(-3.3f, 7.1f)}) {
    (void)texture.evalSpectrum(TexturePoint{uv}, wl);
    (void)texture.evalFloatGradient(TexturePoint{uv});
  }
  if (size >= 4 && std::memcmp(data, "\x89PNG", 4) == 0) (void)readPNG(path);
}

void mergePieceFromBytes(const uint8_t* data, size_t size) {
  const Piece& part2 = fuzzPart2();
  std::string path = writeScratchFile(data, size, ".part1of2.exr");
  rejectingWithInputError([&] {
    Piece piece = loadPiece(path);
    if (!piece.info.part) {
      (void)mergePieces({piece});
      return;
    }
    try {
      (void)mergePieces({piece});  // part 2 is missing
    } catch (const std::runtime_error&) {
    }
    (void)mergePieces({part2, piece});
  });
}

void manifestFromBytes(const uint8_t* data, size_t size) {
  std::string path = writeScratchFile(data, size, ".json");
  rejectingWithInputError([&] { (void)readManifest(path); });
}

void spectraCSVFromBytes(const uint8_t* data, size_t size) {
  std::string path = writeScratchFile(data, size, ".csv");
  (void)readSpectraCSV(path);
}

void layerTextFromBytes(const uint8_t* data, size_t size) {
  FilmStack stack;
  try {
    stack = parseFilmLayers(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const std::invalid_argument& e) {
    throw InputError({}, e.what());
  }
  const LayeredFilm film(RefractiveIndex::keratin(), 1.000277f, 0.6f, stack,
                         Wavelengths::fixed({310.0f, 450.0f, 600.0f, 820.0f}));
  for (float cosine : {1.0f, 0.5f, 0.01f}) {
    const FreeStandingFilm::Reflectance r = film.reflectance(cosine);
    const Spectrum t = film.transmittanceProduct(cosine, 1.0f);
    for (int k = 0; k < kSpectrumSamples; ++k)
      for (float v : {r.s[k], r.p[k], t[k]})
        if (!(v >= -1e-4f && v <= 1.0f + 1e-4f))
          throw std::logic_error("a film's reflectance or transmittance is " + std::to_string(v));
  }
}

void observerTableFromBytes(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  checkObserverCurves(readObserverTable(in, "fuzz.csv", "fuzz"));
}

void observerDefinitionFromBytes(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  checkObserverCurves(makeObserver(readObserverDefinition(in, "fuzz.csv", "fuzz")));
}

void mediumGridFromBytes(const uint8_t* data, size_t size) {
  const VolumeGrid grid = parseVolumeGrid(std::string(reinterpret_cast<const char*>(data), size), "<fuzz>");
  std::shared_ptr<Volume> sigmaT;
  try {
    sigmaT = std::make_shared<GridVolume>(grid, GridVolume::Filter::Trilinear, GridVolume::Wrap::Clamp,
                                          Transform::scale(Vec3(2, 1, 0.5f)));
  } catch (const std::invalid_argument& e) {
    throw InputError({}, e.what());
  }
  const HeterogeneousMedium medium(sigmaT,
                                   std::make_shared<ConstVolume>(SpectralDistribution::constant(0.5f), std::nullopt),
                                   1.0f, std::make_shared<IsotropicPhase>());
  PCG32 rng(7);
  const Wavelengths wl = Wavelengths::fixed({400.0f, 500.0f, 600.0f, 700.0f});
  const Vec3 origins[] = {Vec3(-1, 0.3f, 0.2f), Vec3(1, 0.5f, 0.25f), Vec3(3, 2, 1)};
  for (const Vec3& o : origins)
    for (const Vec3& target : {Vec3(1, 0.6f, 0.25f), Vec3(0.1f, 0.9f, 0.05f), Vec3(1.9f, 0.1f, 0.45f)}) {
      Ray ray{o, normalize(target - o)};
      ray.tmax = 10.0f;
      TrackedTransmittance tr;
      ratioTrack(medium, ray, wl, rng, tr);
      for (int k = 0; k < kSpectrumSamples; ++k)
        if (!(tr.T[k] >= 0.0f && tr.T[k] <= 1.0f) || !std::isfinite(tr.rL[k]))
          throw std::logic_error("a transmittance estimate through the grid is " + std::to_string(tr.T[k]));
    }
}

void numberListFromBytes(const uint8_t* data, size_t size) {
  std::vector<double> values;
  try {
    values = listNumbers(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const std::invalid_argument& e) {
    throw InputError({}, e.what());
  }
  if (values.size() < 2) return;
  std::optional<TabulatedPhase> phase;
  try {
    phase.emplace(values);
  } catch (const std::invalid_argument& e) {
    throw InputError({}, e.what());
  }
  const Vec3 wi = normalize(Vec3(0.3f, -0.2f, 0.9f));
  for (const Vec2& u : {Vec2(0.01f, 0.3f), Vec2(0.5f, 0.5f), Vec2(0.999f, 0.9f)}) {
    const std::optional<PhaseSample> s = phase->sample(wi, u);
    if (!s) continue;
    const float value = phase->eval(wi, s->wo);
    if (!(s->pdf >= 0.0f) || !std::isfinite(s->pdf) || !(std::abs(value - s->pdf) <= 1e-3f * s->pdf + 1e-6f))
      throw std::logic_error("a tabulated phase sample's density is " + std::to_string(s->pdf) +
                             " where its value is " + std::to_string(value));
  }
}

}  // namespace columba::fuzz
