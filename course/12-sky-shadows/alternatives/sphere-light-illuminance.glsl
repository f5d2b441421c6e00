// alternative of: 12-sky-shadows
// written as: the illuminance of a uniform sphere light (Lagarde and de Rousiers 2014), in sin^2(sigma) = (radius / d)^2, over pi
// expected: PASS
// Exercise 12 (optional): shadows of the sky. Handout: course/12-sky-shadows/handout.md

// A sphere of radiance 1 lights p with the illuminance below; the sky it
// hides is the same integral, over pi.
float sphereFormFactor(vec3 p, vec3 n, vec3 centre, float radius) {
    vec3 l = centre - p;
    float sinSigmaSqr = radius * radius / dot(l, l);
    float cosTheta = dot(n, normalize(l));
    float illuminance;
    if (cosTheta * cosTheta > sinSigmaSqr) {
        illuminance = PI * sinSigmaSqr * max(cosTheta, 0.0);
    } else {
        float sinTheta = sqrt(1.0 - cosTheta * cosTheta);
        float x = sqrt(1.0 / sinSigmaSqr - 1.0);
        float y = -x * (cosTheta / sinTheta);
        float sinThetaSqrtY = sinTheta * sqrt(max(1.0 - y * y, 0.0));
        illuminance = (cosTheta * acos(clamp(y, -1.0, 1.0)) - x * sinThetaSqrtY) * sinSigmaSqr + atan(sinThetaSqrtY / x);
    }
    return clamp(illuminance / PI, 0.0, 1.0);
}
