#include "app/default_scene.h"

namespace columba {

std::string defaultSceneXML() {
  return R"(<scene version="3.0.0">
  <default name="spp" value="32"/>
  <default name="res" value="512"/>
  <integrator type="path">
    <integer name="max_depth" value="6"/>
  </integrator>
  <sensor type="perspective">
    <float name="fov" value="35"/>
    <transform name="to_world">
      <lookat origin="0, -4.5, 2.2" target="0, 0, 0.6" up="0, 0, 1"/>
    </transform>
    <film type="hdrfilm">
      <integer name="width" value="$res"/>
      <integer name="height" value="$res"/>
    </film>
    <sampler type="ldsampler">
      <integer name="sample_count" value="$spp"/>
    </sampler>
  </sensor>
  <shape type="sphere">
    <point name="center" x="-0.75" y="0" z="0.7"/>
    <float name="radius" value="0.7"/>
    <bsdf type="roughconductor">
      <float name="alpha" value="0.15"/>
      <rgb name="specular_reflectance" value="0.95, 0.75, 0.45"/>
    </bsdf>
  </shape>
  <shape type="sphere">
    <point name="center" x="0.85" y="0.2" z="0.7"/>
    <float name="radius" value="0.7"/>
    <bsdf type="roughplastic">
      <rgb name="diffuse_reflectance" value="0.1, 0.35, 0.3"/>
      <float name="alpha" value="0.08"/>
    </bsdf>
  </shape>
  <shape type="rectangle">
    <transform name="to_world">
      <scale value="6"/>
    </transform>
    <bsdf type="diffuse">
      <rgb name="reflectance" value="0.45, 0.45, 0.45"/>
    </bsdf>
  </shape>
  <shape type="rectangle">
    <transform name="to_world">
      <scale value="0.8"/>
      <rotate x="1" angle="180"/>
      <translate x="1.5" y="-1" z="4"/>
    </transform>
    <emitter type="area">
      <spectrum name="radiance" value="12"/>
    </emitter>
  </shape>
  <emitter type="constant">
    <spectrum name="radiance" value="0.15"/>
  </emitter>
</scene>
)";
}

}  // namespace columba
