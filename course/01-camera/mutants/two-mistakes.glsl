// mutant of: 01-camera
// mistake: two mistakes at once (+ 0.5 again and no normalize()): no single known mistake explains the numbers, and they fail on every kind of input
// caught by: the check's message or hint contains "of every kind: compare your formula"
// never says: "aspect ratio"
// Exercise 01: camera rays. Handout: course/01-camera/handout.md

// Offset of sample s inside its pixel, for n*n samples per pixel: the centre
// of cell (a, b) of an n x n grid, a = s % n along x, b = s / n along y.
// Returns a point in (0,1)^2; (0.5, 0.5) when n = 1.
vec2 sampleOffset(int s, int n) {
    int a = s - (s / n) * n;
    int b = s / n;
    return (vec2(a, b) + 0.5) / float(n);
}

// Unit direction of the camera ray through pixelSample = (i + sx, j + sy),
// j counted from the BOTTOM row. fovY is the full vertical field of view in
// radians; right, up, forward are the camera's orthonormal basis.
//     x = (2 (i + sx) / width  - 1) * tan(fovY/2) * aspect
//     y = (2 (j + sy) / height - 1) * tan(fovY/2)
//     d = normalize(x right + y up + forward)
vec3 cameraRayDirection(vec2 pixelSample, vec2 resolution, float fovY, vec3 right, vec3 up, vec3 forward) {
    float t = tan(0.5 * fovY);
    float aspect = resolution.x / resolution.y;
    vec2 ndc = 2.0 * (pixelSample + 0.5) / resolution - 1.0;  // MUTANT: + 0.5 again  // (-1, 1) across the image
    float x = ndc.x * t * aspect;
    float y = ndc.y * t;
    return x * right + y * up + forward;  // MUTANT: not normalised
}
