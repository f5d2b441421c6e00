#!/usr/bin/env bash
# Packs a built raylab for a machine that has a GPU driver but no Debian
# packages (docs/performance.md, "On a GPU"): the stripped binary, the shared
# libraries it loads (Debian 12's, less glibc), a stand-in libOSMesa.so.8
# (the OSMesa fallback is never used there, and the real one drags in 120 MB
# of LLVM), glvnd's EGL/GL loader packages as .debs, and what raylab reads at
# run time (shaders/, scenes/, solutions/, exercises/, the bench scenes).
#
#   scripts/gpu-package.sh BUILD_DIR OUT_DIR
#
# On the GPU machine, from OUT_DIR's parent (scripts/gpu-bench.sh does this):
#   for f in OUT/gl/*.deb; do dpkg -x $f /; done; ldconfig
#   LD_LIBRARY_PATH=OUT/lib:/usr/local/nvidia/lib64 RAYLAB_ROOT=OUT/root \
#   __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json \
#   OUT/bin/raylab bench ...
set -euo pipefail
build=${1:?usage: scripts/gpu-package.sh BUILD_DIR OUT_DIR}
out=${2:?usage: scripts/gpu-package.sh BUILD_DIR OUT_DIR}
src=$(cd "$(dirname "$0")/.." && pwd)
bin="$build/bin/raylab"
[ -x "$bin" ] || { echo "gpu-package.sh: $bin: not built" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/gl" "$out/root/tests/bench"
strip -o "$out/bin/raylab" "$bin"

# The stand-in OSMesa: every entry point fails, so raylab's EGL path is the one used.
cat > "$out/osmesa-stub.c" <<'EOF'
#include <stddef.h>
void* OSMesaCreateContextAttribs(const int* a, void* s) { (void)a; (void)s; return NULL; }
void OSMesaDestroyContext(void* c) { (void)c; }
int OSMesaMakeCurrent(void* c, void* b, unsigned t, int w, int h) { (void)c; (void)b; (void)t; (void)w; (void)h; return 0; }
void* OSMesaGetProcAddress(const char* n) { (void)n; return NULL; }
EOF
cc -shared -fPIC -O2 -Wl,-soname,libOSMesa.so.8 -o "$out/lib/libOSMesa.so.8" "$out/osmesa-stub.c"
rm "$out/osmesa-stub.c"

# Every library ldd lists, less glibc's own, OSMesa's tree and the GL loaders
# (those come from the .debs, unpacked into / there as the device README says).
skip='^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so|libOSMesa|libglapi|libLLVM|libz3|libicu|libxml2|libedit|libtinfo|libffi|libEGL|libGL|libOpenGL|libGLdispatch|libGLX)'
ldd "$bin" | awk '/=> \//{print $1, $3}' | while read -r name path; do
    if ! echo "$name" | grep -Eq "$skip"; then cp -L "$path" "$out/lib/$name"; fi
done
# libglfw (linked, used only for windows) loads X11 libraries that ldd above
# listed through OSMesa's tree too; add those glfw needs.
for lib in $(ldd "$(ldd "$bin" | awk '/libglfw/{print $3}')" | awk '/=> \//{print $1}'); do
    if [ ! -e "$out/lib/$lib" ] && ! echo "$lib" | grep -Eq "$skip"; then
        cp -L "$(ldd "$(ldd "$bin" | awk '/libglfw/{print $3}')" | awk -v l="$lib" '$1==l{print $3}')" "$out/lib/$lib"
    fi
done

(cd "$out/gl" && apt-get download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 >/dev/null)

cp -r "$src/shaders" "$src/scenes" "$out/root/"
[ -d "$src/solutions" ] && cp -r "$src/solutions" "$out/root/"
[ -d "$src/exercises" ] && cp -r "$src/exercises" "$out/root/"
cp "$src"/tests/bench/*.json "$out/root/tests/bench/"
cp "$src/scripts/gpu-bench.sh" "$out/"
du -sh "$out"
