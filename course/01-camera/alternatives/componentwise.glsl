// alternative of: 01-camera
// written as: the ray one component at a time, the sample grid with % and integer vectors
// expected: PASS (a correct solution written differently)
// Exercise 01: camera rays. Handout: course/01-camera/handout.md

// Offset of sample s inside its pixel, for n*n samples per pixel: the centre
// of cell (a, b) of an n x n grid, a = s % n along x, b = s / n along y.
// Returns a point in (0,1)^2; (0.5, 0.5) when n = 1.
vec2 sampleOffset(int s, int n) {
    ivec2 cell = ivec2(s % n, s / n);
    return (vec2(cell) + vec2(0.5)) / float(n);
}

// Unit direction of the camera ray through pixelSample = (i + sx, j + sy),
// j counted from the BOTTOM row. fovY is the full vertical field of view in
// radians; right, up, forward are the camera's orthonormal basis.
//     x = (2 (i + sx) / width  - 1) * tan(fovY/2) * aspect
//     y = (2 (j + sy) / height - 1) * tan(fovY/2)
//     d = normalize(x right + y up + forward)
vec3 cameraRayDirection(vec2 pixelSample, vec2 resolution, float fovY, vec3 right, vec3 up, vec3 forward) {
    float halfHeight = tan(fovY / 2.0);
    float halfWidth = halfHeight * resolution.x / resolution.y;
    float x = (2.0 * pixelSample.x / resolution.x - 1.0) * halfWidth;
    float y = (2.0 * pixelSample.y / resolution.y - 1.0) * halfHeight;
    vec3 d = forward + x * right + y * up;
    return d / length(d);
}
