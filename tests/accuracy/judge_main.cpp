// judge: the true picture of a scene file (metamorphic/exact_oracle.h: the model
// with no ray offset, its geometry in long double) and how far other pictures of it are from it.
//     build/bin/judge SCENE TRUTH.png [PICTURE.png...]
// writes TRUTH.png and prints, per picture, the share of pixels off by more
// than 1/255 and the mean difference in 1/255 (issue #10's budgets: 0.25%,
// 0.1). docs/numerics.md uses it for the before/after figures.
#include "accuracy/accuracy_support.h"
#include "metamorphic/exact_oracle.h"

#include "core/error.h"
#include "core/scene_io.h"

#include <cstdio>
#include <iostream>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: judge SCENE TRUTH.png [PICTURE.png...]\n";
        return 2;
    }
    try {
        rl::Scene scene = rl::loadSceneFile(argv[1]).scene;
        rl::Rendering truth = rl::meta::renderOracle(scene);
        rl::writePng(argv[2], truth.display);
        for (int k = 3; k < argc; ++k) {
            rl::Rendering picture;
            picture.display = rl::readPng(argv[k]);
            rl::ImageDiff d = rl::compareRenderings(picture, truth);
            std::printf("%s: off %.3f%% mean %.3f/255 max %d\n", argv[k], 100 * d.offFraction, d.meanLsb, d.maxLsb);
        }
    } catch (const rl::Error& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
    return 0;
}
