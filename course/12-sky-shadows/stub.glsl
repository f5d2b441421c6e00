// Exercise 12 (optional): shadows of the sky. Handout: course/12-sky-shadows/handout.md
//
// Until you write this, no sphere shadows the sky's diffuse light: a sphere
// resting on the ground lacks the soft contact shadow around it (a sun's
// sharp shadow, which the framework computes, stays).

// The share of the environment's diffuse light at p (unit normal n) that the
// sphere (centre, radius) hides: its form factor, the cosine-weighted solid
// angle of the cap it covers over pi. p lies outside the sphere. With
//     d = |centre - p|,  w = (centre - p) / d,  h = d / radius,  cos(beta) = n . w
//   the whole sphere above the horizon (h cos(beta) >= 1):   F = cos(beta) / h^2
//   the whole sphere below it          (h cos(beta) <= -1):  F = 0
//   otherwise, with x = sqrt(h^2 - 1), k = sqrt(1 - h^2 cos(beta)^2):
//     F = ( (cos(beta) acos(-x cos(beta) / sin(beta)) - x k) / h^2 + atan(k / x) ) / pi
float sphereFormFactor(vec3 p, vec3 n, vec3 centre, float radius) {
    return NOT_STARTED;  // TODO
}
