#pragma once
// The readers Columba fuzzes, each as a function of raw bytes. Shared by the libFuzzer entry points
// (fuzz/fuzz_*.cpp) and the regression replay in the unit suite (tests/io/test_fuzz_regressions.cpp).
//
// Each function returns normally when the input was read (and the object built from it), and
// throws InputError when the input is rejected; any other exception escapes for the caller to
// report, and a crash or sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

namespace columba::fuzz {

// Scene XML through loadSceneString and Scene construction. Lines at the start of the form
// `-Dname=value` are -D defines; the rest is the XML. Relative file names resolve against
// `baseDir`. A malformed -D name (the command line's error) is reported as an InputError.
void sceneFromBytes(const uint8_t* data, size_t size, const std::string& baseDir);
// Mesh PLY (readPlyMesh, then a TriangleMesh).
void plyMeshFromBytes(const uint8_t* data, size_t size);
// Feather PLY (readFeatherPly, then a FeatherShape).
void featherPlyFromBytes(const uint8_t* data, size_t size);
// Wavefront OBJ (readObjMesh, then a TriangleMesh).
void objMeshFromBytes(const uint8_t* data, size_t size);
// Mitsuba serialized mesh (parseSerializedMesh of its first and second mesh, then a TriangleMesh).
void serializedMeshFromBytes(const uint8_t* data, size_t size);
// Mitsuba grid volume (parseVolumeGrid, then an SDF grid shape, its voxels' bounds and a few rays
// through them).
void sdfGridFromBytes(const uint8_t* data, size_t size);
// OpenEXR image (readEXR, then an environment map and a few lookups).
void exrEnvmapFromBytes(const uint8_t* data, size_t size);
// Radiance HDR image, or any other the bitmap reader takes (readLinearRGBImage, then an environment
// map and a few lookups).
void hdrEnvmapFromBytes(const uint8_t* data, size_t size);
// Image file of any format a bitmap texture reads (readImagePixels, decoded from sRGB and raw,
// then a raw texture and a few lookups); a PNG is also read through readPNG, as `fit --mask` and
// `montage` read it.
void bitmapFromBytes(const uint8_t* data, size_t size);
// A piece of a split render (loadPiece), merged alone and, if it is a part, after part 2 of 2 of
// a 16 x 16 frame, which part 1 of fuzz/seeds/merge_piece completes. loadPiece and mergePieces
// reject bad pieces with std::runtime_error naming the file: reported as an InputError.
void mergePieceFromBytes(const uint8_t* data, size_t size);
// A sweep's manifest (readManifest), which rejects bad input with std::runtime_error: reported as
// an InputError.
void manifestFromBytes(const uint8_t* data, size_t size);
// A table of measured spectra (readSpectraCSV).
void spectraCSVFromBytes(const uint8_t* data, size_t size);
// A barbule's layer text (parseFilmLayers, which rejects bad text with std::invalid_argument:
// reported as an InputError), then the film of a keratin cortex over it at a few wavelengths and
// angles, whose R and T must be numbers in [0, 1] (else std::logic_error).
void layerTextFromBytes(const uint8_t* data, size_t size);

// An observer's table of sensitivities (readObserverTable), its observer's curves required to be
// finite, non-negative and of area 1 (else std::logic_error).
void observerTableFromBytes(const uint8_t* data, size_t size);
// An observer's definition by its cones' parameters (readObserverDefinition, then makeObserver),
// its curves held to the same.
void observerDefinitionFromBytes(const uint8_t* data, size_t size);

// A Mitsuba grid volume (parseVolumeGrid, then a gridvolume) as the extinction of a heterogeneous
// medium, with ratio tracking along a few rays through it: every transmittance estimate must be a
// finite number in [0, 1] (else std::logic_error), and each walk ends (the majorant grid's bounds
// and the tracking's caps).
void mediumGridFromBytes(const uint8_t* data, size_t size);
// A list parameter's text (listNumbers, as tabphase's values and barbulearms' arm_tilts are read),
// then, with two or more numbers, a tabulated phase function of them, evaluated and sampled: its
// values and densities must be finite and not negative, a sample's density its value (else
// std::logic_error).
void numberListFromBytes(const uint8_t* data, size_t size);

// The readers take paths: the bytes are written to a file of this process named with `suffix`
// (".ply", ".obj", ".exr"), which is returned.
std::string writeScratchFile(const uint8_t* data, size_t size, const std::string& suffix);

}  // namespace columba::fuzz
