// mutant of: 12-sky-shadows
// mistake: the sphere's cap never clipped by the horizon: cos(beta) / h^2 everywhere
// caught by: the check's message or hint contains "only the part above it counts"
// Exercise 12 (optional): shadows of the sky. Handout: course/12-sky-shadows/handout.md

// The sphere's form factor seen from p: the share of the cosine-weighted
// hemisphere around n that its cap covers, clipped by the horizon where the
// cap crosses it (Snyder 1996).
float sphereFormFactor(vec3 p, vec3 n, vec3 centre, float radius) {
    vec3 toCentre = centre - p;
    float d = length(toCentre);
    float h = d / radius;
    float cosBeta = dot(n, toCentre / d);
    float h2 = h * h;
    float k2 = 1.0 - h2 * cosBeta * cosBeta;
    return max(cosBeta, 0.0) / h2;  // wholly above (or wholly below) the horizon
    float x = sqrt(h2 - 1.0);
    float sinBeta = sqrt(max(1.0 - cosBeta * cosBeta, 0.0));
    float k = sqrt(k2);
    float clipped = (cosBeta * acos(clamp(-x * cosBeta / sinBeta, -1.0, 1.0)) - x * k) / h2 + atan(k, x);
    return clamp(clipped / PI, 0.0, 1.0);
}
