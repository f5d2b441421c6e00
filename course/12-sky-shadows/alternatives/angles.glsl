// alternative of: 12-sky-shadows
// written as: the branches chosen by angles (the cap's half-angle sigma = asin(radius / d) against the horizon's distance pi/2 - beta), sin(beta) as |n x w|, cot(sigma) as sqrt(h^2 - 1)
// expected: PASS
// Exercise 12 (optional): shadows of the sky. Handout: course/12-sky-shadows/handout.md

float sphereFormFactor(vec3 p, vec3 n, vec3 centre, float radius) {
    vec3 w = normalize(centre - p);
    float sinSigma = radius / distance(centre, p);
    float cosBeta = clamp(dot(n, w), -1.0, 1.0);
    float horizonAngle = asin(cosBeta);  // pi/2 - beta: how far above the horizon w is
    float sigma = asin(sinSigma);
    if (horizonAngle >= sigma) return cosBeta * sinSigma * sinSigma;  // wholly above the horizon
    if (-horizonAngle >= sigma) return 0.0;                            // wholly below it
    float cotSigma = sqrt(max(1.0 / (sinSigma * sinSigma) - 1.0, 0.0));
    float sinBeta = length(cross(n, w));
    float k = sqrt(max(1.0 - cosBeta * cosBeta / (sinSigma * sinSigma), 0.0));
    float a = acos(clamp(-cotSigma * cosBeta / sinBeta, -1.0, 1.0));
    return clamp(((cosBeta * a - cotSigma * k) * sinSigma * sinSigma + atan(k, cotSigma)) / PI, 0.0, 1.0);
}
