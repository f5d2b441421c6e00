// camera.glsl: the pinhole camera as the host hands it over (docs/uniforms.md).
// The host computes in double and hands over what float32 can carry
// (docs/uniforms.md): the position in the scene block (cameraFromAnchor,
// scene.glsl), a zero column here, and tan(fov_y / 2) folded into the third column, so that u_fovY is
// pi/2 (tan(u_fovY / 2) = 1) and fields of view up to 180 degrees stay exact.
uniform mat4 u_cameraToWorld;  // columns: right, up, back / tan(fov_y / 2) (back = -forward), position (0)
uniform float u_fovY;          // pi/2: the field of view is in the third column
uniform vec2 u_resolution;     // render target size in pixels
uniform int u_spp;             // samples per pixel, a square number n*n

// Where every camera ray starts, relative to the scene's anchor (scene.glsl).
vec3 cameraPosition() { return cameraFromAnchor(); }

// The field of view handed to exercise 01: the uniform (always pi/2), or in a
// program built for pictures the constant, so that tan(fovY / 2) = 1 folds
// instead of running per pixel (llvmpipe has no per-draw constant folding).
float cameraFovY() {
#ifdef RL_PICTURE_ONLY
    return 0.5 * PI;
#else
    return u_fovY;
#endif
}

// The camera's basis (columns of u_cameraToWorld) and the picture's size;
// a program for one picture gets them as constants (RL_CAMERA_RIGHT, ...:
// app/render/define_table.cpp), so that exercise 01's ray folds.
vec3 cameraRight() {
#ifdef RL_CAMERA_RIGHT
    return RL_CAMERA_RIGHT;
#else
    return u_cameraToWorld[0].xyz;
#endif
}
vec3 cameraUp() {
#ifdef RL_CAMERA_UP
    return RL_CAMERA_UP;
#else
    return u_cameraToWorld[1].xyz;
#endif
}
// forward / tan(fov_y / 2): the same directions as forward with fov_y.
vec3 cameraForward() {
#ifdef RL_CAMERA_BACK
    return -RL_CAMERA_BACK;
#else
    return -u_cameraToWorld[2].xyz;
#endif
}
vec2 resolution() {
#ifdef RL_RESOLUTION
    return RL_RESOLUTION;
#else
    return u_resolution;
#endif
}

// The direction of sample s (of n*n) in the pixel whose lower-left corner is
// `pixel` (column i, row j from the bottom), by exercise 01.
vec3 primaryRayDirection(vec2 pixel, int s, int n) {
    vec2 offset = sampleOffset(s, n);
    return cameraRayDirection(pixel + offset, resolution(), cameraFovY(), cameraRight(), cameraUp(), cameraForward());
}
