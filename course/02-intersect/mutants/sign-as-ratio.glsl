// mutant of: 02-intersect
// mistake: the sign of b as b / abs(b): 0 / 0 = NaN from the centre of a sphere (b = 0 for every ray), so q and the root are NaN there (issue 35: it was told about sign(0))
// caught by: the check's message or hint contains "b / abs(b) is 0 / 0 = NaN"
// Exercise 02: ray/sphere intersection. Handout: course/02-intersect/handout.md

// Distance t > 0 along the unit direction `dir` to the nearest point where
// the ray origin + t dir meets the sphere, or NO_HIT.
// Numerically stable form (Haines et al., "Precision Improvements for
// Ray/Sphere Intersection", Ray Tracing Gems, 2019, ch. 7):
//     f = origin - center,  b = dot(f, dir)
//     discriminant = r^2 - |f - b dir|^2     (perpendicular distance: no cancellation of b^2 - c)
//     q = -b - sign(b) sqrt(discriminant),   roots t0 = c / q, t1 = q,  c = |f|^2 - r^2
float intersectSphere(vec3 origin, vec3 dir, vec3 center, float radius) {
    vec3 f = origin - center;
    float b = dot(f, dir);
    vec3 perpendicular = f - b * dir;
    float discriminant = radius * radius - dot(perpendicular, perpendicular);
    if (discriminant < 0.0) return NO_HIT;
    float c = dot(f, f) - radius * radius;
    float q = -b - (b / abs(b)) * sqrt(discriminant);
    if (q == 0.0) return NO_HIT;  // origin on the surface, ray tangent: nothing ahead
    float t0 = c / q;
    float t1 = q;
    if (t0 > t1) {
        float swap = t0;
        t0 = t1;
        t1 = swap;
    }
    if (t0 > 0.0) return t0;  // the near root, in front of the origin
    if (t1 > 0.0) return t1;  // origin inside the sphere: the far root
    return NO_HIT;            // sphere behind the origin
}
