// Exercise 02: ray/sphere intersection. Handout: course/02-intersect/handout.md
//
// Until you write this, no sphere is ever hit (background and stripes).

// Distance t > 0 along the UNIT direction `dir` to the nearest point where
// origin + t dir lies on the sphere (center, radius), or NO_HIT.
// Contract: the nearest root with t > 0; when the origin is inside the
// sphere that is the far root; a sphere behind the origin is a miss.
// Use the numerically stable form (the handout explains why):
//     f = origin - center,  b = dot(f, dir),  c = dot(f, f) - radius^2
//     discriminant = radius^2 - |f - b dir|^2
//     q = -b - sign(b) sqrt(discriminant),  roots: c / q and q
// (careful: GLSL's sign(0.0) is 0; here sign(b) must be +1 when b = 0)
float intersectSphere(vec3 origin, vec3 dir, vec3 center, float radius) {
    return NOT_STARTED;  // TODO
}
