// Exercise 05: the GGX normal distribution. Handout: course/05-ggx/handout.md
//
// Until you write this, there are no specular highlights.

// GGX / Trowbridge-Reitz NDF for unit normal n and unit half vector h:
//     D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)
// alpha is already roughness^2 (exercise 08 computes it). The handout shows
// a form that stays accurate in float32 near the peak (n.h -> 1).
float D_GGX(vec3 n, vec3 h, float alpha) {
    return NOT_STARTED;  // TODO
}
