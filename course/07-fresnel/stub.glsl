// Exercise 07: Schlick's Fresnel.       Handout: course/07-fresnel/handout.md
//
// Until you write this, there are no specular highlights.

// Fresnel reflectance for base reflectance F0 (linear) and VoH = dot(v, h):
//     F = F0 + (1 - F0) (1 - clamp(VoH, 0, 1))^5
vec3 F_Schlick(vec3 F0, float VoH) {
    return vec3(NOT_STARTED);  // TODO
}
