#include <gtest/gtest.h>

#include <png.h>
#include <stb_image_write.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>

#include "bsdfs/bsdf.h"
#include "builtin/builtin_plugins.h"
#include "core/illuminant.h"
#include "core/rng.h"
#include "emitters/envmap_emitter.h"
#include "io/image.h"
#include "scene/scene.h"
#include "support/bsdf_test_support.h"
#include "support/error_test_support.h"
#include "support/image_test_support.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"
#include "textures/bitmap_texture.h"
#include "textures/checkerboard_texture.h"

using namespace columba;
using namespace columba::testing;

namespace {

Wavelengths someWavelengths() { return Wavelengths::fixed({420, 500, 580, 660}); }

// The linear RGB of a spectrum seen as a reflectance under D65, by quadrature at 1 nm: an
// independent account of what colour a texture's spectrum has.
Vec3 colourOf(const std::function<float(float)>& spectrum) {
  Vec3 xyz(0, 0, 0);
  double white = 0;
  for (float l = kLambdaMin; l <= kLambdaMax; l += 1.0f) {
    xyz += cieXYZ(l) * (d65(l) * spectrum(l));
    white += cieXYZ(l).y * d65(l);
  }
  return xyzToLinearRGB(xyz / float(white));
}

// A 2 x 2 grey EXR, rows from the top: 0.1 0.3 / 0.5 0.7.
std::string writeGreyQuad(const std::filesystem::path& dir) {
  Image quad(2, 2);
  const float values[4] = {0.1f, 0.3f, 0.5f, 0.7f};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) quad.rgb[3 * i + c] = values[i];
  std::string path = (dir / "quad.exr").string();
  writeEXR(path, quad);
  return path;
}

std::shared_ptr<BitmapTexture> bitmap(const std::string& path, TextureFilter filter, TextureWrap wrap, bool raw = false,
                                      Transform toUV = Transform()) {
  return std::make_shared<BitmapTexture>(readImagePixels(path, !raw), raw, filter, wrap, toUV);
}

class Textures : public TempDirTest {
 protected:
  std::string errorOfScene(const std::string& body) {
    try {
      loadSceneString("<scene version=\"3.0.0\">\n" + body + "\n</scene>", (dir_ / "t.xml").string(), dir_.string(), {},
                      builtinPlugins());
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

}  // namespace

TEST(Checkerboard, AlternatesInHalfUnitSquaresAsMitsubas) {
  CheckerboardTexture checks(SpectralDistribution::constant(0.4f), SpectralDistribution::constant(0.2f), Transform());
  const Wavelengths wl = someWavelengths();
  // Colours: color0 where the fractional parts of u and v are on the same side of 1/2 (Mitsuba's
  // eval). Single values the other way round (Mitsuba's eval_1 tests mask.x != mask.y).
  for (const auto& [uv, same] : {std::pair{Vec2(0.25f, 0.25f), true},
                                 {Vec2(0.75f, 0.75f), true},
                                 {Vec2(0.75f, 0.25f), false},
                                 {Vec2(0.25f, 0.75f), false},
                                 {Vec2(-0.25f, 0.25f), false},  // fractional part of -0.25 is 0.75
                                 {Vec2(3.25f, -1.75f), true}}) {
    EXPECT_FLOAT_EQ(checks.evalSpectrum(uv, wl)[2], same ? 0.4f : 0.2f) << uv.x << " " << uv.y;
    EXPECT_FLOAT_EQ(checks.evalFloat(uv), same ? 0.2f : 0.4f) << uv.x << " " << uv.y;
  }
  EXPECT_FLOAT_EQ(checks.mean(), 0.3f);

  // to_uv scales before the lookup: (0.3, 0.1) becomes (0.6, 0.2).
  CheckerboardTexture scaled(SpectralDistribution::constant(0.4f), SpectralDistribution::constant(0.2f),
                             Transform::scale(Vec3(2, 2, 1)));
  EXPECT_FLOAT_EQ(scaled.evalSpectrum(Vec2(0.3f, 0.1f), wl)[0], 0.2f);
  EXPECT_FLOAT_EQ(scaled.evalSpectrum(Vec2(0.1f, 0.1f), wl)[0], 0.4f);
}

TEST(BitmapTexture, WrapModesIndexAsDefined) {
  // repeat: period 4; mirror: the image, then the image reversed (period 8); clamp: the edge.
  EXPECT_EQ(wrapTexelIndex(-1, 4, TextureWrap::Repeat), 3);
  EXPECT_EQ(wrapTexelIndex(5, 4, TextureWrap::Repeat), 1);
  EXPECT_EQ(wrapTexelIndex(-1, 4, TextureWrap::Mirror), 0);
  EXPECT_EQ(wrapTexelIndex(-4, 4, TextureWrap::Mirror), 3);
  EXPECT_EQ(wrapTexelIndex(-5, 4, TextureWrap::Mirror), 3);
  EXPECT_EQ(wrapTexelIndex(4, 4, TextureWrap::Mirror), 3);
  EXPECT_EQ(wrapTexelIndex(6, 4, TextureWrap::Mirror), 1);
  EXPECT_EQ(wrapTexelIndex(8, 4, TextureWrap::Mirror), 0);
  EXPECT_EQ(wrapTexelIndex(-3, 4, TextureWrap::Clamp), 0);
  EXPECT_EQ(wrapTexelIndex(9, 4, TextureWrap::Clamp), 3);
  EXPECT_EQ(wrapTexelIndex(2, 4, TextureWrap::Clamp), 2);
}

TEST_F(Textures, BitmapLookupsInterpolateBetweenTexelCentres) {
  const std::string path = writeGreyQuad(dir_);
  auto linear = bitmap(path, TextureFilter::Bilinear, TextureWrap::Repeat);
  ASSERT_EQ(linear->width(), 2);
  // Texel centres at (i + 1/2) / 2; v runs down the image from its top row.
  EXPECT_NEAR(linear->evalFloat(Vec2(0.25f, 0.25f)), 0.1f, 1e-6f);
  EXPECT_NEAR(linear->evalFloat(Vec2(0.75f, 0.25f)), 0.3f, 1e-6f);
  EXPECT_NEAR(linear->evalFloat(Vec2(0.25f, 0.75f)), 0.5f, 1e-6f);
  EXPECT_NEAR(linear->evalFloat(Vec2(0.5f, 0.5f)), 0.4f, 1e-6f);  // the mean of all four
  EXPECT_NEAR(linear->evalFloat(Vec2(0.5f, 0.25f)), 0.2f, 1e-6f);
  EXPECT_NEAR(linear->mean(), 0.4f, 1e-6f);
  // At the left edge, half of the column beyond it: the right column (repeat), the left (mirror,
  // clamp).
  EXPECT_NEAR(linear->evalFloat(Vec2(0.0f, 0.25f)), 0.2f, 1e-6f);
  EXPECT_NEAR(bitmap(path, TextureFilter::Bilinear, TextureWrap::Mirror)->evalFloat(Vec2(0.0f, 0.25f)), 0.1f, 1e-6f);
  EXPECT_NEAR(bitmap(path, TextureFilter::Bilinear, TextureWrap::Clamp)->evalFloat(Vec2(0.0f, 0.75f)), 0.5f, 1e-6f);
  // Nearest: the texel the point lies in.
  auto nearest = bitmap(path, TextureFilter::Nearest, TextureWrap::Repeat);
  EXPECT_NEAR(nearest->evalFloat(Vec2(0.9f, 0.1f)), 0.3f, 1e-6f);
  EXPECT_NEAR(nearest->evalFloat(Vec2(0.1f, 0.9f)), 0.5f, 1e-6f);
  EXPECT_NEAR(nearest->evalFloat(Vec2(1.1f, 1.9f)), 0.5f, 1e-6f);
  // to_uv: a half-texel shift moves a lookup from one centre to the next.
  auto shifted =
      bitmap(path, TextureFilter::Bilinear, TextureWrap::Repeat, false, Transform::translate(Vec3(0.5f, 0, 0)));
  EXPECT_NEAR(shifted->evalFloat(Vec2(0.25f, 0.25f)), 0.3f, 1e-6f);
  // A grey image gives the same number at every wavelength.
  Spectrum s = linear->evalSpectrum(Vec2(0.75f, 0.75f), someWavelengths());
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(s[i], 0.7f, 1e-6f);
}

TEST_F(Textures, ColourTexelsBecomeSpectraOfTheirColour) {
  Image colours(2, 1);
  const Vec3 red(0.8f, 0.2f, 0.1f), blue(0.1f, 0.3f, 0.7f);
  for (int c = 0; c < 3; ++c) {
    colours.rgb[c] = red[c];
    colours.rgb[3 + c] = blue[c];
  }
  writeEXR((dir_ / "colours.exr").string(), colours);
  auto texture = bitmap((dir_ / "colours.exr").string(), TextureFilter::Bilinear, TextureWrap::Clamp);
  // Each texel's spectrum, seen under D65, has the texel's colour.
  for (auto [u, expected] : {std::pair{0.25f, red}, std::pair{0.75f, blue}}) {
    Vec3 rgb = colourOf([&](float l) {
      return texture->evalSpectrum(Vec2(u, 0.5f), Wavelengths::fixed({l, l, l, l}))[0];
    });
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], expected[c], 0.01f) << "u " << u << " channel " << c;
    EXPECT_NEAR(texture->evalFloat(Vec2(u, 0.5f)), linearRGBToXYZ(expected).y, 1e-5f);
  }
  // Between the centres the spectra are blended (as Mitsuba does), not the colours.
  const Wavelengths wl = someWavelengths();
  Spectrum left = texture->evalSpectrum(Vec2(0.25f, 0.5f), wl), right = texture->evalSpectrum(Vec2(0.75f, 0.5f), wl);
  Spectrum quarter = texture->evalSpectrum(Vec2(0.375f, 0.5f), wl);
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(quarter[i], 0.75f * left[i] + 0.25f * right[i], 1e-5f);
}

TEST_F(Textures, EightBitFilesAreDecodedFromSRGBUnlessRaw) {
  Image grey(1, 1);
  std::fill(grey.rgb.begin(), grey.rgb.end(), 0.5f);
  const std::string png = (dir_ / "grey.png").string();
  writePNG(png, grey);
  const unsigned char stored = toSRGB8(0.5f);
  EXPECT_NEAR(bitmap(png, TextureFilter::Nearest, TextureWrap::Repeat)->evalFloat(Vec2(0.5f, 0.5f)),
              srgbToLinear(stored / 255.0f), 1e-5f);
  EXPECT_NEAR(bitmap(png, TextureFilter::Nearest, TextureWrap::Repeat, true)->evalFloat(Vec2(0.5f, 0.5f)),
              stored / 255.0f, 1e-5f);
}

TEST_F(Textures, SixteenBitPNGsKeepTheirPrecision) {
  // One grey 16-bit sample, stored as given (libpng's simplified writer, linear format).
  const std::string path = (dir_ / "deep.png").string();
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = image.height = 1;
  image.format = PNG_FORMAT_LINEAR_Y;
  const uint16_t sample = 40000;
  ASSERT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, &sample, 0, nullptr));
  EXPECT_NEAR(bitmap(path, TextureFilter::Nearest, TextureWrap::Repeat, true)->evalFloat(Vec2(0.5f, 0.5f)),
              40000.0f / 65535.0f, 1e-6f);
  EXPECT_NEAR(bitmap(path, TextureFilter::Nearest, TextureWrap::Repeat)->evalFloat(Vec2(0.5f, 0.5f)),
              srgbToLinear(40000.0f / 65535.0f), 1e-6f);
}

TEST_F(Textures, RadianceHDREnvironmentMapsLoadLikeEXRs) {
  // 0.5 and 0.25 are exact in Radiance's shared-exponent format.
  const int w = 8, h = 4;
  std::vector<float> pixels(size_t(w) * h * 3);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = (i / 3) % 2 ? 0.5f : 0.25f;
  const std::string hdr = (dir_ / "sky.hdr").string(), exr = (dir_ / "sky.exr").string();
  ASSERT_TRUE(stbi_write_hdr(hdr.c_str(), w, h, 3, pixels.data()));
  Image image(w, h);
  image.rgb = pixels;
  writeEXR(exr, image);

  auto envmapOf = [&](const std::string& file) {
    ParsedScene parsed =
        loadSceneString("<scene version=\"3.0.0\"><emitter type=\"envmap\"><string name=\"filename\" value=\"" + file +
                            "\"/></emitter></scene>",
                        (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
    return std::dynamic_pointer_cast<EnvmapEmitter>(parsed.objects.at(0));
  };
  auto fromHDR = envmapOf(hdr), fromEXR = envmapOf(exr);
  ASSERT_TRUE(fromHDR && fromEXR);
  const Wavelengths wl = someWavelengths();
  for (Vec3 d : {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0.3f, -0.5f, 0.8f)}) {
    Spectrum a = fromHDR->radianceFromDirection(normalize(d), wl), b = fromEXR->radianceFromDirection(normalize(d), wl);
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_FLOAT_EQ(a[i], b[i]);
  }
}

TEST_F(Textures, CheckerboardReflectanceRendersItsPattern) {
  // A plate lit straight from above with irradiance pi: L = albedo, the checkerboard's values.
  // to_uv puts the image centre in the middle of a color0 square; a point one unit away along
  // either axis lies in the middle of a color1 square, whichever way the image is oriented.
  std::string xml = R"(<scene version="3.0.0"><integrator type="direct"/>
    <sensor type="perspective"><float name="fov" value="45"/>
      <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="64"/><integer name="height" value="64"/>
        <rfilter type="box"/></film>
      <sampler type="ldsampler"><integer name="sample_count" value="64"/></sampler></sensor>
    <texture type="checkerboard" id="checks">
      <transform name="to_uv"><scale x="10" y="10"/><translate x="0.25" y="0.25"/></transform>
    </texture>
    <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform>
      <bsdf type="diffuse"><ref name="reflectance" id="checks"/></bsdf></shape>
    <emitter type="directional"><vector name="direction" x="0" y="0" z="-1"/>
      <spectrum name="irradiance" value="3.14159265"/></emitter>
    </scene>)";
  Image image = renderSceneString(xml);
  // One world unit is 64 / (2 * 5 * tan(22.5 degrees)) = 15.45 pixels.
  auto at = [&](int x, int y) { return meanColour(image, x, y, x + 2, y + 2); };
  for (auto [x, y, albedo] : {std::tuple{31, 31, 0.4f}, std::tuple{46, 31, 0.2f}, std::tuple{16, 31, 0.2f},
                              std::tuple{31, 46, 0.2f}, std::tuple{46, 46, 0.4f}, std::tuple{16, 46, 0.4f}}) {
    Vec3 c = at(x, y);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], albedo, 0.02f * albedo) << x << ", " << y << " channel " << k;
  }
}

TEST_F(Textures, MaskOpacityAndBlendWeightTakeTextures) {
  // Left texel 0, right texel 1: the mask is open on the left half and shut on the right.
  writeTwoTexelEXR((dir_ / "half.exr").string(), 0.0f, 1.0f);
  ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0">
    <texture type="bitmap" id="half"><string name="filename" value="half.exr"/></texture>
    <bsdf type="mask"><ref name="opacity" id="half"/><bsdf type="diffuse"/></bsdf>
    <bsdf type="blendbsdf"><ref name="weight" id="half"/>
      <bsdf type="diffuse"><float name="reflectance" value="0.2"/></bsdf>
      <bsdf type="diffuse"><float name="reflectance" value="0.8"/></bsdf></bsdf></scene>)",
                                       (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
  ASSERT_EQ(parsed.objects.size(), 2u);
  auto mask = std::dynamic_pointer_cast<BSDF>(parsed.objects[0]);
  auto blend = std::dynamic_pointer_cast<BSDF>(parsed.objects[1]);
  ASSERT_TRUE(mask && blend);
  const Wavelengths wl = someWavelengths();
  const Vec3 up(0, 0, 1);
  auto at = [](float u) { return BSDFContext{Vec2(u, 0.5f), Vec3(), Vec3()}; };
  EXPECT_FLOAT_EQ(mask->passThrough(at(0.25f), up, wl)[0], 1.0f);
  EXPECT_FLOAT_EQ(mask->passThrough(at(0.75f), up, wl)[0], 0.0f);
  EXPECT_FLOAT_EQ(mask->passThrough(at(0.5f), up, wl)[0], 0.5f);
  // The blend is the first BSDF where the weight is 0 and the second where it is 1.
  EXPECT_NEAR(blend->eval(at(0.25f), up, up, wl)[0], 0.2f / kPi, 1e-6f);
  EXPECT_NEAR(blend->eval(at(0.75f), up, up, wl)[0], 0.8f / kPi, 1e-6f);
}

TEST_F(Textures, MistakesAreNamedWithTheirLine) {
  writeGreyQuad(dir_);
  expectContains(errorOfScene(R"(<texture type="bitmap" id="t"><string name="filename" value="quad.exr"/>
  <string name="wrap_mode" value="wrap"/></texture>)"),
                 {"t.xml:3", "unknown wrap_mode 'wrap'"});
  expectContains(errorOfScene(R"(<texture type="bitmap" id="t"><string name="filename" value="quad.exr"/>
  <string name="filter_type" value="trilinear"/></texture>)"),
                 {"t.xml:3", "unknown filter_type 'trilinear'"});
  expectContains(
      errorOfScene(R"(<texture type="bitmap" id="t"><string name="filename" value="missing.png"/></texture>)"),
      {"t.xml:2", "missing.png"});
  std::ofstream(dir_ / "broken.png") << "not an image";
  expectContains(
      errorOfScene(R"(<texture type="bitmap" id="t"><string name="filename" value="broken.png"/></texture>)"),
      {"t.xml:2", "broken.png", "cannot read the image"});
  expectContains(errorOfScene(R"(<bsdf type="diffuse"><rgb name="reflectance" value="0.5"/>
  <texture type="checkerboard" name="reflectance"/></bsdf>)"),
                 {"t.xml:2", "'reflectance' is given both as a value and as a texture"});
  Image colour(1, 1);
  colour.rgb = {0.9f, 0.1f, 0.1f};
  writeEXR((dir_ / "colour.exr").string(), colour);
  expectContains(errorOfScene(R"(<bsdf type="diffuse"><texture type="bitmap" name="reflectance">
  <string name="filename" value="colour.exr"/><boolean name="raw" value="true"/></texture></bsdf>)"),
                 {"t.xml:2", "raw numbers, not colours"});
}

TEST_F(Textures, Fp16FormatRoundsTexelsToHalfPrecision) {
  writeTwoTexelEXR((dir_ / "tenth.exr").string(), 0.1f, 0.3f);
  // A mask's pass-through is 1 - the opacity texture, looked up at the left texel's centre.
  auto passThrough = [&](const std::string& format) {
    ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0">
    <bsdf type="mask"><texture type="bitmap" name="opacity"><string name="filename" value="tenth.exr"/>)" +
                                             format + R"(</texture><bsdf type="diffuse"/></bsdf></scene>)",
                                         (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
    const auto mask = std::dynamic_pointer_cast<BSDF>(parsed.objects.at(0));
    return mask->passThrough(BSDFContext{Vec2(0.25f, 0.5f), Vec3(), Vec3()}, Vec3(0, 0, 1), someWavelengths())[0];
  };
  // The texel as the texture holds it: its luminance, from float or from half-precision channels.
  auto texel = [](float value) {
    PixelGrid grid{1, 1, 3, {value, value, value}};
    return BitmapTexture(grid, false, TextureFilter::Nearest, TextureWrap::Repeat, Transform())
        .evalFloat(Vec2(0.5f, 0.5f));
  };
  const float half = 0.0999755859375f;  // 0.1 in half precision
  EXPECT_FLOAT_EQ(passThrough(""), 1.0f - texel(0.1f));
  EXPECT_FLOAT_EQ(passThrough(R"(<string name="format" value="variant"/>)"), 1.0f - texel(0.1f));
  EXPECT_FLOAT_EQ(passThrough(R"(<string name="format" value="fp16"/>)"), 1.0f - texel(half));
  EXPECT_NE(texel(half), texel(0.1f));
  expectContains(errorOfScene(R"(<texture type="bitmap" id="t"><string name="filename" value="tenth.exr"/>
  <string name="format" value="uint16"/></texture>)"),
                 {"t.xml:3", "unknown format 'uint16'"});
  // A texel beyond half's largest value (65504) would become infinite: refused, naming it.
  writeTwoTexelEXR((dir_ / "bright.exr").string(), 0.5f, 70000.0f);
  expectContains(errorOfScene(R"(<texture type="bitmap" id="t"><string name="filename" value="bright.exr"/>
  <string name="format" value="fp16"/></texture>)"),
                 {"t.xml:3",
                  "bright.exr': the texel at x 1, y 0, channel 0 is 70000, beyond half precision's largest "
                  "value 65504"});
  EXPECT_EQ(errorOfScene(R"(<texture type="bitmap" id="t"><string name="filename" value="bright.exr"/></texture>)"),
            "");
}

TEST_F(Textures, RoughnessTexturesChooseTheDistributionAtEachPoint) {
  // A checkerboard of roughness 0.4 and 0.05: at each point the BSDF equals the one with that
  // roughness everywhere.
  auto bsdfOf = [](const std::string& type, const std::string& alpha) {
    return loadBSDF(type, "<string name=\"distribution\" value=\"ggx\"/>" + alpha);
  };

  const std::string checks =
      R"(<texture type="checkerboard" name="alpha"><float name="color0" value="0.4"/>
         <float name="color1" value="0.05"/></texture>)";
  const Wavelengths wl = someWavelengths();
  const Vec3 wi = normalize(Vec3(0.3f, 0.1f, 0.9f)), wo = normalize(Vec3(-0.2f, 0.25f, 0.8f));
  const Vec3 below = normalize(Vec3(0.1f, -0.2f, -0.9f));
  for (const std::string type : {"roughconductor", "roughdielectric"}) {
    auto textured = bsdfOf(type, checks);
    auto rough = bsdfOf(type, "<float name=\"alpha\" value=\"0.4\"/>");
    auto smooth = bsdfOf(type, "<float name=\"alpha\" value=\"0.05\"/>");
    ASSERT_TRUE(textured && rough && smooth) << type;
    // A single value takes color0 where the fractional parts of u and v lie on opposite sides of
    // 1/2 (Mitsuba's eval_1; the Checkerboard test below).
    const BSDFContext inColor0{Vec2(0.75f, 0.25f), Vec3(), Vec3()}, inColor1{Vec2(0.25f, 0.25f), Vec3(), Vec3()};
    for (const Vec3& out : {wo, below}) {
      EXPECT_FLOAT_EQ(textured->eval(inColor0, wi, out, wl)[0], rough->eval(inColor0, wi, out, wl)[0]) << type;
      EXPECT_FLOAT_EQ(textured->eval(inColor1, wi, out, wl)[0], smooth->eval(inColor1, wi, out, wl)[0]) << type;
      EXPECT_FLOAT_EQ(textured->pdf(inColor0, wi, out, wl), rough->pdf(inColor0, wi, out, wl)) << type;
      EXPECT_FLOAT_EQ(textured->pdf(inColor1, wi, out, wl), smooth->pdf(inColor1, wi, out, wl)) << type;
    }
    auto s = textured->sample(inColor1, wi, wl, 0.3f, Vec2(0.4f, 0.6f));
    auto t = smooth->sample(inColor1, wi, wl, 0.3f, Vec2(0.4f, 0.6f));
    ASSERT_EQ(bool(s), bool(t)) << type;
    if (s) {
      EXPECT_FLOAT_EQ(s->pdf, t->pdf) << type;
    }
  }
  // roughplastic's roughness is a constant, as in Mitsuba.
  expectContains(errorOfScene("<bsdf type=\"roughplastic\">" + checks + "</bsdf>"),
                 {"t.xml:2", "roughness cannot be a texture"});
}

TEST_F(Textures, ASpotLightProjectsItsTexture) {
  // Texels 0.25 (left) and 1 (right); the light looks along +z with a 30-degree cutoff, so a
  // direction with x / z = tan(30 degrees) / 2 meets the right texel's centre (u = 3/4) and its
  // mirror image the left one's, both inside the full-intensity beam (22.5 degrees).
  writeTwoTexelEXR((dir_ / "slide.exr").string(), 0.25f, 1.0f);
  ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0"><emitter type="spot">
      <float name="cutoff_angle" value="30"/>
      <texture type="bitmap" name="texture"><string name="filename" value="slide.exr"/></texture>
    </emitter></scene>)",
                                       (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
  auto spot = std::dynamic_pointer_cast<Emitter>(parsed.objects.at(0));
  ASSERT_TRUE(spot);
  const float x = 0.5f * std::tan(30.0f * kPi / 180.0f);
  const Wavelengths wl = someWavelengths();
  // A point at distance along (x, 0, 1) from the light sees it along -(x, 0, 1).
  auto right = spot->sample(Vec3(x, 0, 1), Vec2(0.5f, 0.5f), wl),
       left = spot->sample(Vec3(-x, 0, 1), Vec2(0.5f, 0.5f), wl);
  ASSERT_TRUE(right && left);
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(right->radiance[i] / left->radiance[i], 4.0f, 1e-4f);
}

TEST_F(Textures, ARawConstantIsItsNumberEverywhere) {
  ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0"><bsdf type="diffuse">
      <texture type="rawconstant" name="reflectance"><float name="value" value="0.3"/></texture></bsdf></scene>)",
                                       (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
  auto bsdf = std::dynamic_pointer_cast<BSDF>(parsed.objects.at(0));
  ASSERT_TRUE(bsdf);
  const Vec3 up(0, 0, 1);
  const Spectrum f = bsdf->eval({}, up, up, someWavelengths());
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_FLOAT_EQ(f[i], 0.3f * kInvPi);
  // Three numbers are not a colour, nor one number.
  expectContains(errorOfScene(R"(<bsdf type="diffuse"><texture type="rawconstant" name="reflectance">
  <vector name="value" value="0.1, 0.2, 0.3"/></texture></bsdf>)"),
                 {"t.xml:2", "raw numbers, not colours"});
  expectContains(errorOfScene(R"(<bsdf type="roughconductor"><texture type="rawconstant" name="alpha">
  <vector name="value" value="0.1, 0.2, 0.3"/></texture></bsdf>)"),
                 {"t.xml:2", "holds three numbers"});
  expectContains(errorOfScene(R"(<texture type="rawconstant" id="t"/>)"), {"t.xml:2", "needs its 'value'"});
}

TEST_F(Textures, AConductorsIndexMayBeATexture) {
  // k is 2 on the left half of the image and 4 on the right (nearest lookups); eta is 0.5. At
  // normal incidence the mirror reflects ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) on each half.
  writeTwoTexelEXR((dir_ / "k.exr").string(), 2.0f, 4.0f);
  for (const char* type : {"conductor", "roughconductor"}) {
    ParsedScene parsed =
        loadSceneString(std::string(R"(<scene version="3.0.0"><bsdf type=")") + type + R"(">
        <float name="eta" value="0.5"/>)" +
                            (std::string(type) == "roughconductor" ? R"(<float name="alpha" value="0.001"/>)" : "") +
                            R"(<texture type="bitmap" name="k"><string name="filename" value="k.exr"/>
          <string name="filter_type" value="nearest"/></texture></bsdf></scene>)",
                        (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
    auto bsdf = std::dynamic_pointer_cast<BSDF>(parsed.objects.at(0));
    ASSERT_TRUE(bsdf);
    for (auto [u, kValue] : {std::pair{0.25f, 2.0f}, std::pair{0.75f, 4.0f}}) {
      BSDFContext ctx{Vec2(u, 0.5f), Vec3(), Vec3()};
      const float expected = (0.25f + kValue * kValue) / (2.25f + kValue * kValue);
      // The rough metal at alpha 0.001: its albedo, the mean weight of its samples.
      double sum = 0;
      const int n = 2000;
      PCG32 rng(3, 5);
      for (int s = 0; s < n; ++s) {
        auto sample = bsdf->sample(ctx, Vec3(0, 0, 1), someWavelengths(), rng.nextFloat(),
                                   Vec2(rng.nextFloat(), rng.nextFloat()));
        if (sample) sum += sample->weight[1];
      }
      EXPECT_NEAR(sum / n, expected, 2e-3) << type << " at u = " << u;
    }
  }
}

TEST_F(Textures, AnAreaLightsRadianceMayBeATexture) {
  // A 2 x 2 rectangle whose radiance is the default checkerboard (0.4 where u and v are both below
  // 1/2 or both above, 0.2 elsewhere), taken as the texture gives it (no D65: Mitsuba 3 hands a
  // texture given to an emitter over unchanged). Seen directly and sampled from a point above, each
  // quadrant sends its own radiance.
  ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0">
      <shape type="rectangle"><emitter type="area"><texture type="checkerboard" name="radiance"/></emitter></shape>
    </scene>)",
                                       (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
  Scene scene(parsed, {"t.xml", 0});
  const Emitter& light = *scene.emitters().front();
  const Wavelengths wl = someWavelengths();
  // uv = ((x + 1) / 2, (y + 1) / 2) on Mitsuba's rectangle.
  auto expected = [](float x, float y) { return (x < 0) == (y < 0) ? 0.4f : 0.2f; };
  for (auto [x, y] : {std::pair{-0.5f, -0.5f}, std::pair{0.5f, -0.5f}, std::pair{0.5f, 0.5f}, std::pair{-0.5f, 0.5f}}) {
    auto hit = scene.intersect(Ray{Vec3(x, y, 2), Vec3(0, 0, -1)});
    ASSERT_TRUE(hit);
    const Spectrum seen = light.radianceAt(*hit, Vec3(0, 0, 1), wl);
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(seen[i], expected(x, y), 1e-6f);
  }
  PCG32 rng(7, 1);
  const Vec3 ref(0.1f, -0.2f, 1.0f);
  int quadrants[4] = {0, 0, 0, 0};
  for (int n = 0; n < 200; ++n) {
    auto s = light.sample(ref, Vec2(rng.nextFloat(), rng.nextFloat()), wl);
    ASSERT_TRUE(s);
    const Vec3 p = ref + s->direction * s->distance;
    if (std::abs(p.x) < 1e-3f || std::abs(p.y) < 1e-3f) continue;  // on a border
    ++quadrants[(p.x > 0 ? 1 : 0) + (p.y > 0 ? 2 : 0)];
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(s->radiance[i], expected(p.x, p.y), 1e-6f);
  }
  for (int q : quadrants) EXPECT_GT(q, 20);
}
