#include "builtin/builtin_plugins.h"

#include "bsdfs/barbulearms.h"
#include "bsdfs/barbulebsdf.h"
#include "bsdfs/blendbsdf.h"
#include "bsdfs/bumpmap.h"
#include "bsdfs/conductor.h"
#include "bsdfs/dielectric.h"
#include "bsdfs/diffuse.h"
#include "bsdfs/mask.h"
#include "bsdfs/normalmap.h"
#include "bsdfs/null.h"
#include "bsdfs/plastic.h"
#include "bsdfs/principled.h"
#include "bsdfs/principledthin.h"
#include "bsdfs/roughconductor.h"
#include "bsdfs/roughdielectric.h"
#include "bsdfs/roughplastic.h"
#include "bsdfs/thindielectric.h"
#include "bsdfs/twosided.h"
#include "emitters/area_emitter.h"
#include "emitters/constant_emitter.h"
#include "emitters/directional_emitter.h"
#include "emitters/envmap_emitter.h"
#include "emitters/point_emitter.h"
#include "emitters/projector_emitter.h"
#include "emitters/spot_emitter.h"
#include "film/box_filter.h"
#include "film/film.h"
#include "film/gaussian_filter.h"
#include "film/tent_filter.h"
#include "integrators/direct_integrator.h"
#include "integrators/moment_integrator.h"
#include "integrators/particle_tracer_integrator.h"
#include "integrators/path_integrator.h"
#include "integrators/volpath_integrator.h"
#include "media/blend_phase.h"
#include "media/const_volume.h"
#include "media/grid_volume.h"
#include "media/heterogeneous_medium.h"
#include "media/hg_phase.h"
#include "media/homogeneous_medium.h"
#include "media/isotropic_phase.h"
#include "media/rayleigh_phase.h"
#include "media/tabulated_phase.h"
#include "samplers/independent_sampler.h"
#include "samplers/low_discrepancy_sampler.h"
#include "samplers/multijitter_sampler.h"
#include "samplers/stratified_sampler.h"
#include "sensors/bsdf_visualizer_sensor.h"
#include "sensors/orthographic_sensor.h"
#include "sensors/perspective_sensor.h"
#include "sensors/thin_lens_sensor.h"
#include "shapes/cylinder_shape.h"
#include "shapes/disk_shape.h"
#include "shapes/feather_shape.h"
#include "shapes/instance_shape.h"
#include "shapes/obj_mesh.h"
#include "shapes/ply_mesh.h"
#include "shapes/rectangle_shape.h"
#include "shapes/sdf_grid_shape.h"
#include "shapes/serialized_mesh.h"
#include "shapes/shape_group.h"
#include "shapes/sphere_shape.h"
#include "shapes/triangle_mesh.h"
#include "textures/bitmap_texture.h"
#include "textures/checkerboard_texture.h"
#include "textures/mesh_attribute_texture.h"
#include "textures/raw_constant_texture.h"

namespace columba {

const PluginRegistry& builtinPlugins() {
  static const PluginRegistry registry = [] {
    PluginRegistry r;
    r.add("integrator", "path", makePathIntegrator);
    r.add("integrator", "direct", makeDirectIntegrator);
    r.add("integrator", "ptracer", makeParticleTracerIntegrator);
    r.add("integrator", "moment", makeMomentIntegrator);
    r.add("integrator", "volpath", makeVolumetricPathIntegrator);
    r.add("integrator", "volpathmis", makeVolumetricPathIntegrator);
    r.add("sensor", "perspective", makePerspectiveSensor);
    r.add("sensor", "thinlens", makeThinLensSensor);
    r.add("sensor", "orthographic", makeOrthographicSensor);
    r.add("sensor", "bsdfvisualizer", makeBSDFVisualizerSensor);
    r.add("film", "hdrfilm", makeHDRFilm);
    r.add("rfilter", "box", makeBoxFilter);
    r.add("rfilter", "gaussian", makeGaussianFilter);
    r.add("rfilter", "tent", makeTentFilter);
    r.add("sampler", "independent", makeIndependentSampler);
    r.add("sampler", "stratified", makeStratifiedSampler);
    r.add("sampler", "ldsampler", makeLowDiscrepancySampler);
    r.add("sampler", "multijitter", makeMultijitterSampler);
    r.add("emitter", "area", makeAreaEmitter);
    r.add("emitter", "constant", makeConstantEmitter);
    r.add("emitter", "point", makePointEmitter);
    r.add("emitter", "spot", makeSpotEmitter);
    r.add("emitter", "projector", makeProjectorEmitter);
    r.add("emitter", "directional", makeDirectionalEmitter);
    r.add("emitter", "envmap", makeEnvmapEmitter);
    r.add("bsdf", "diffuse", makeDiffuseBSDF);
    r.add("bsdf", "roughplastic", makeRoughPlasticBSDF);
    r.add("bsdf", "plastic", makePlasticBSDF);
    r.add("bsdf", "dielectric", makeDielectricBSDF);
    r.add("bsdf", "roughconductor", makeRoughConductorBSDF);
    r.add("bsdf", "conductor", makeConductorBSDF);
    r.add("bsdf", "twosided", makeTwoSidedBSDF);
    r.add("bsdf", "thindielectric", makeThinDielectricBSDF);
    r.add("bsdf", "roughdielectric", makeRoughDielectricBSDF);
    r.add("bsdf", "principled", makePrincipledBSDF);
    r.add("bsdf", "principledthin", makePrincipledThinBSDF);
    r.add("bsdf", "null", makeNullBSDF);
    r.add("bsdf", "mask", makeMaskBSDF);
    r.add("bsdf", "blendbsdf", makeBlendBSDF);
    r.add("bsdf", "normalmap", makeNormalMapBSDF);
    r.add("bsdf", "bumpmap", makeBumpMapBSDF);
    r.add("bsdf", "barbulearms", makeBarbuleArmsBSDF);
    r.add("bsdf", "barbulebsdf", makeBarbuleBSDF);
    r.add("bsdf", "barbulebsdfev", makeBarbuleBSDFEv);
    r.add("shape", "obj", makeObjShape);
    r.add("shape", "ply", makePlyShape);
    r.add("shape", "serialized", makeSerializedShape);
    r.add("shape", "rectangle", makeRectangleShape);
    r.add("shape", "disk", makeDiskShape);
    r.add("shape", "sphere", makeSphereShape);
    r.add("shape", "cylinder", makeCylinderShape);
    r.add("shape", "sdfgrid", makeSDFGridShape);
    r.add("shape", "cube", makeCubeShape);
    r.add("shape", "feather", makeFeatherShape);
    r.add("texture", "bitmap", makeBitmapTexture);
    r.add("texture", "checkerboard", makeCheckerboardTexture);
    r.add("texture", "mesh_attribute", makeMeshAttributeTexture);
    r.add("texture", "rawconstant", makeRawConstantTexture);
    r.add("medium", "homogeneous", makeHomogeneousMedium);
    r.add("medium", "heterogeneous", makeHeterogeneousMedium);
    r.add("phase", "isotropic", makeIsotropicPhase);
    r.add("phase", "hg", makeHenyeyGreensteinPhase);
    r.add("phase", "rayleigh", makeRayleighPhase);
    r.add("phase", "blendphase", makeBlendPhase);
    r.add("phase", "tabphase", makeTabulatedPhase);
    r.add("volume", "constvolume", makeConstVolume);
    r.add("volume", "gridvolume", makeGridVolume);
    r.add("shape", "shapegroup", makeShapeGroup);
    r.add("shape", "instance", makeInstanceShape);
    return r;
  }();
  return registry;
}

}  // namespace columba
