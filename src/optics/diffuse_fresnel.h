#pragma once
// Fresnel reflectance averaged over cosine-weighted (diffuse) illumination.

namespace columba {

// 2 * integral over mu in [0, 1] of F(mu, eta) mu: the fraction of light arriving uniformly in
// projected solid angle that a smooth dielectric interface reflects. eta = n_transmitted /
// n_incident; eta < 1 (from inside a denser medium) includes total internal reflection.
float fresnelDiffuseReflectance(float eta);

}  // namespace columba
