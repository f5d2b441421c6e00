// Exercise 01: camera rays.            Handout: course/01-camera/handout.md
//
// Until you write these, the framework looks straight ahead from every pixel
// and paints grey/magenta stripes (NOT STARTED). Check with:
//     ./raylab check --exercise 1

// Offset of sample s inside its pixel, for n*n samples per pixel.
// Contract: the centre of cell (a, b) of an n x n grid over the unit square,
//     a = s % n (along x),  b = s / n (along y),  offset = ((a + 0.5)/n, (b + 0.5)/n)
// so n = 1 gives (0.5, 0.5), the pixel centre.
vec2 sampleOffset(int s, int n) {
    return vec2(NOT_STARTED);  // TODO
}

// Unit direction of the camera ray through pixelSample = (i + sx, j + sy),
// column i from the left, row j from the BOTTOM. fovY: full vertical field
// of view in radians. right, up, forward: the camera's orthonormal basis.
// Contract (spec, "Camera"), with t = tan(fovY / 2), aspect = width / height:
//     x = (2 (i + sx) / width  - 1) * t * aspect
//     y = (2 (j + sy) / height - 1) * t
//     d = normalize(x right + y up + forward)
vec3 cameraRayDirection(vec2 pixelSample, vec2 resolution, float fovY, vec3 right, vec3 up, vec3 forward) {
    return vec3(NOT_STARTED);  // TODO
}
