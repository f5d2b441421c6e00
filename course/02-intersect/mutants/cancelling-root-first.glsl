// mutant of: 02-intersect
// mistake: the near root -b - sqrt(discriminant) straight from the formula and the far root as c / t0: right in exact arithmetic, but for b < 0 and c ~ 0 (an origin on or just inside the surface, looking in) -b - sqrt(discriminant) cancels and c / t0 is noise
// caught by: the check's message or hint contains "must come from c / q"
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
    float t0 = -b - sqrt(discriminant);  // MUTANT: the near root straight from the formula
    if (t0 > 0.0) return t0;
    float t1 = c / t0;                   // MUTANT: the far root from t0 t1 = c
    if (t1 > 0.0) return t1;
    return NO_HIT;            // sphere behind the origin
}
