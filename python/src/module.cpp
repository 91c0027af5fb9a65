// The `columba._columba` extension: Columba's renderer, barbule model, optics and feather
// generator for numpy. Everything here calls the C++ library; nothing is computed twice.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "builtin/builtin_plugins.h"
#include "builtin/default_scene.h"
#include "core/error.h"
#include "core/version.h"
#include "core/warning_listener.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace py = pybind11;

namespace columba::python {

void bindModel(py::module_& m);   // model.cpp: the barbule BSDF, optics, feathers
void bindFit(py::module_& m);     // fit.cpp: parameter fits to images and spectra
void bindVision(py::module_& m);  // vision.cpp: avian visual models
// The category of Columba's warnings in Python (columba.ColumbaWarning, a UserWarning).
PyObject* columbaWarning();

PyObject* columbaWarning() {
  static PyObject* category = PyErr_NewException("columba.ColumbaWarning", PyExc_UserWarning, nullptr);
  return category;
}

namespace {

// Columba's warnings since they were last taken, from whichever thread warned (a render's workers
// warn with the GIL released): Python reissues them as ColumbaWarnings (columba/__init__.py).
std::mutex warningsMutex;
std::vector<std::string> warnings;

// A loaded scene with what it was loaded from.
struct PyScene {
  ParsedScene parsed;
  std::shared_ptr<Scene> scene;
  std::string source;
};

std::shared_ptr<PyScene> makeScene(ParsedScene parsed, const std::string& source) {
  auto s = std::make_shared<PyScene>();
  s->parsed = std::move(parsed);
  s->source = source;
  s->scene = std::make_shared<Scene>(s->parsed, SourceLocation{source, 0});
  return s;
}

std::shared_ptr<PyScene> loadFile(const std::string& path, const Defines& defines) {
  // The CLI's own check and message.
  if (!std::filesystem::is_regular_file(path))
    throw InputError({}, "scene file '" + path + "' does not exist or is not a regular file");
  ParsedScene parsed;
  {
    py::gil_scoped_release release;
    parsed = loadSceneFile(path, defines, builtinPlugins());
  }
  return makeScene(std::move(parsed), path);
}

std::shared_ptr<PyScene> loadString(const std::string& xml, const std::string& name, const std::string& baseDir,
                                    const Defines& defines) {
  ParsedScene parsed;
  {
    py::gil_scoped_release release;
    parsed = loadSceneString(xml, name, baseDir, defines, builtinPlugins());
  }
  return makeScene(std::move(parsed), name);
}

std::shared_ptr<PyScene> loadDefault(const Defines& defines) {
  ParsedScene parsed;
  {
    py::gil_scoped_release release;
    parsed = loadDefaultScene(defines);
  }
  return makeScene(std::move(parsed), "<default scene>");
}

}  // namespace

// An Image's RGB as an H x W x 3 float32 array that owns the image (no copy).
py::array_t<float> imageArray(Image&& image) {
  auto* owned = new Image(std::move(image));
  py::capsule owner(owned, [](void* p) { delete static_cast<Image*>(p); });
  return py::array_t<float>({py::ssize_t(owned->height), py::ssize_t(owned->width), py::ssize_t(3)}, owned->rgb.data(),
                            owner);
}

namespace {

// An image's cone catches as a dict of H x W arrays named after the cones (empty without them).
py::dict coneArrays(const Image& image) {
  py::dict cones;
  const size_t k = image.cones.count();
  for (size_t c = 0; c < k; ++c) {
    py::array_t<float> plane({py::ssize_t(image.height), py::ssize_t(image.width)});
    float* out = plane.mutable_data();
    for (size_t p = 0; p < size_t(image.width) * size_t(image.height); ++p) out[p] = image.cones.values[p * k + c];
    cones[py::str(image.cones.names[c])] = plane;
  }
  return cones;
}

// Renders on a worker thread while the calling thread, without the GIL, looks for signals every
// 50 ms: Ctrl-C (or any Python signal handler that raises) stops the render before its next
// sample and the exception propagates.
py::tuple renderScene(const PyScene& s, int spp, uint64_t seed, int threads, bool adaptive, double targetError) {
  RenderSettings settings;
  settings.samplesPerPixel = spp;
  settings.seed = seed;
  settings.threads = threads;
  settings.adaptive = adaptive || targetError > 0.0;
  settings.targetError = targetError;
  settings.validate({"spp", "threads", "target_error", "bins"});
  if (spp == 0) settings.samplesPerPixel = s.scene->sensor().sampler().sampleCount();
  std::atomic<bool> cancel{false};
  settings.cancel = &cancel;

  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  Image image;
  RenderStats stats;
  std::exception_ptr failure;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        image = renderImage(*s.scene, settings, stats);
      } catch (...) {
        failure = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(mutex);
      done = true;
      finished.notify_all();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) {
      lock.unlock();
      {
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) {
          interrupted = true;
          cancel = true;
        }
      }
      lock.lock();
      if (interrupted) break;
    }
    lock.unlock();
    worker.join();
  }
  if (interrupted) throw py::error_already_set();
  if (failure) {
    try {
      std::rethrow_exception(failure);
    } catch (const std::runtime_error& e) {  // settings the renderer refuses (adaptive with too few spp)
      if (!dynamic_cast<const InputError*>(&e)) throw py::value_error(e.what());
      throw;
    }
  }
  py::dict info;
  if (image.cones.count() > 0) info["cones"] = coneArrays(image);
  info["seconds"] = stats.seconds;
  info["samples"] = stats.samples;
  info["rays"] = stats.rays;
  info["non_finite_samples"] = stats.nonFiniteSamples;
  info["spp"] = settings.samplesPerPixel;
  info["seed"] = seed;
  if (settings.adaptive) {
    info["pilot_samples"] = stats.pilotSamples;
    info["fewest_samples"] = stats.fewestSamples;
    info["most_samples"] = stats.mostSamples;
    info["predicted_relative_error"] = stats.predictedRelativeError;
  }
  return py::make_tuple(imageArray(std::move(image)), info);
}

}  // namespace

Image imageFromArray(const py::array& input) {
  auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(input);
  if (!a || a.ndim() != 3 || a.shape(2) != 3)
    throw py::value_error("an image must be an H x W x 3 array of linear RGB values");
  if (a.shape(0) < 1 || a.shape(1) < 1) throw py::value_error("an image must have at least one pixel");
  Image image(int(a.shape(1)), int(a.shape(0)));
  std::copy(a.data(), a.data() + a.size(), image.rgb.begin());
  return image;
}

namespace {

void writeImage(const std::string& path, const py::array& array) {
  ImageFormat format = checkOutputImagePath(path);
  Image image = imageFromArray(array);
  py::gil_scoped_release release;
  if (format == ImageFormat::EXR)
    writeEXR(path, image);
  else
    writePNG(path, image);
}

Image readImageFile(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".exr" && ext != ".png")
    throw InputError({path, 0}, "cannot read '" + ext + "' images (only .exr and .png)");
  py::gil_scoped_release release;
  return ext == ".exr" ? readEXR(path) : readPNG(path);
}

}  // namespace
}  // namespace columba::python

PYBIND11_MODULE(_columba, m) {
  using namespace columba;
  using namespace columba::python;
  m.doc() = "Columba: spectral rendering of iridescent rock dove feathers (the C++ core)";
  m.attr("__version__") = kColumbaVersion;
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  m.attr("ColumbaWarning") = py::handle(columbaWarning());
  setWarningListener([](const std::string& text) {
    std::lock_guard<std::mutex> lock(warningsMutex);
    warnings.push_back(text);
  });
  m.def(
      "_take_warnings",
      [] {
        std::lock_guard<std::mutex> lock(warningsMutex);
        return std::exchange(warnings, {});
      },
      "Columba's warnings (FILE:LINE: message) since the last call, oldest first");

  py::class_<PyScene, std::shared_ptr<PyScene>>(m, "Scene", "A loaded scene (columba.load_file, load_string)")
      .def_property_readonly("source", [](const PyScene& s) { return s.source; })
      .def_property_readonly("width", [](const PyScene& s) { return s.scene->sensor().film().width(); })
      .def_property_readonly("height", [](const PyScene& s) { return s.scene->sensor().film().height(); })
      .def_property_readonly("spp", [](const PyScene& s) { return s.scene->sensor().sampler().sampleCount(); })
      .def_property_readonly("shape_count", [](const PyScene& s) { return s.scene->shapeCount(); })
      .def_property_readonly("primitive_count", [](const PyScene& s) { return s.scene->primitiveCount(); })
      .def_property_readonly("unused_defines", [](const PyScene& s) { return s.parsed.unusedDefines; })
      .def("__repr__", [](const PyScene& s) {
        return "<columba.Scene " + s.source + " " + std::to_string(s.scene->sensor().film().width()) + "x" +
               std::to_string(s.scene->sensor().film().height()) + ">";
      });

  m.def("_load_file", &loadFile, py::arg("path"), py::arg("defines"));
  m.def("_load_string", &loadString, py::arg("xml"), py::arg("name"), py::arg("base_dir"), py::arg("defines"));
  m.def("_load_default", &loadDefault, py::arg("defines"));
  m.def("_render", &renderScene, py::arg("scene"), py::arg("spp"), py::arg("seed"), py::arg("threads"),
        py::arg("adaptive"), py::arg("target_error"));
  m.def("write_image", &writeImage, py::arg("path"), py::arg("image"),
        "Writes an H x W x 3 linear RGB array as .exr (float32) or .png (8-bit sRGB)");
  m.def(
      "_read_image",
      [](const std::string& path) {
        Image image = readImageFile(path);
        py::object centres = py::none(), bands = py::none();
        if (image.spectral.count() > 0) {
          size_t k = image.spectral.count();
          centres = py::array_t<float>(py::ssize_t(k), image.spectral.centres.data());
          bands = py::array_t<float>({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(k)},
                                     image.spectral.values.data());
        }
        image.spectral = {};
        return py::make_tuple(imageArray(std::move(image)), centres, bands);
      },
      py::arg("path"));
  m.def(
      "_read_cones", [](const std::string& path) { return coneArrays(readImageFile(path)); }, py::arg("path"));
  m.def("to_srgb", py::vectorize(toSRGB8), py::arg("linear"),
        "The 8-bit sRGB encoding of linear values (uint8), as PNGs are written");
  m.def("from_srgb", py::vectorize(srgbToLinear), py::arg("encoded"),
        "The linear value of sRGB-encoded values in [0, 1]");
  bindModel(m);
  bindFit(m);
  bindVision(m);
}
