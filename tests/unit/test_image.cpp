// Image files, the 8-bit quantisation and the comparison metrics of
// core/image.h, on small hand-made images whose answers are worked out here.
#include "core/error.h"
#include "core/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

namespace fs = std::filesystem;
using rl::DisplayImage;
using rl::RadianceImage;
using rl::Rendering;

namespace {

// A fresh directory per test, removed afterwards (CTest runs tests in parallel).
class ImageFiles : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "raylab-test-image-XXXXXX").string();
        ASSERT_NE(mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

std::string floatBytesLE(float v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    std::string s;
    for (int k = 0; k < 4; ++k) s.push_back(char(bits >> (8 * k)));
    return s;
}

DisplayImage display(int w, int h, std::uint8_t value = 0) {
    return DisplayImage{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3, value)};
}

// Expects `f` to throw rl::Error whose message contains every one of `parts`.
template <typename F>
void expectErrorMentioning(F f, std::initializer_list<std::string> parts) {
    try {
        f();
        FAIL() << "no rl::Error thrown";
    } catch (const rl::Error& e) {
        for (const auto& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
    }
}

}  // namespace

// ---- Files -----------------------------------------------------------------

TEST_F(ImageFiles, PngRoundTripKeepsEveryByteAndTheRowOrder) {
    DisplayImage image = display(3, 2);
    for (std::size_t k = 0; k < image.rgb.size(); ++k) image.rgb[k] = std::uint8_t(k * 14 + 1);
    rl::writePng(path("a.png"), image);
    DisplayImage back = rl::readPng(path("a.png"));
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.height, 2);
    EXPECT_EQ(back.rgb, image.rgb);
}

TEST_F(ImageFiles, PfmRoundTripIsBitExactIncludingNonFiniteValues) {
    RadianceImage image{2, 2, {0.0f, -1.5f, 1e-30f, 3.25f, 1e30f, 0.1f,
                               std::numeric_limits<float>::infinity(), 7.0f, 8.0f,
                               std::numeric_limits<float>::quiet_NaN(), -0.0f, 12.0f}};
    rl::writePfm(path("a.pfm"), image);
    RadianceImage back = rl::readPfm(path("a.pfm"));
    ASSERT_EQ(back.width, 2);
    ASSERT_EQ(back.height, 2);
    ASSERT_EQ(back.rgb.size(), image.rgb.size());
    EXPECT_EQ(std::memcmp(back.rgb.data(), image.rgb.data(), image.rgb.size() * sizeof(float)), 0);
}

TEST_F(ImageFiles, PfmStoresTheBottomRowFirstAsLittleEndianFloats) {
    RadianceImage image{1, 2, {1.0f, 2.0f, 3.0f,    // row 0, the top
                               4.0f, 5.0f, 6.0f}};  // row 1, the bottom
    rl::writePfm(path("a.pfm"), image);
    std::string expected = "PF\n1 2\n-1.0\n";
    for (float v : {4.0f, 5.0f, 6.0f, 1.0f, 2.0f, 3.0f}) expected += floatBytesLE(v);
    EXPECT_EQ(readBytes(path("a.pfm")), expected);
    // 4.0f is 0x40800000: little endian puts the 0x40 last.
    EXPECT_EQ(expected.substr(12, 4), std::string("\x00\x00\x80\x40", 4));
}

TEST_F(ImageFiles, ReadsBigEndianAndGreyscalePfm) {
    // Scale +1: big endian. 1 x 2 greyscale, bottom row 0.5, top row 2.0.
    std::string bytes = "Pf\n1 2\n1.0\n";
    for (float v : {0.5f, 2.0f}) {
        std::string le = floatBytesLE(v);
        bytes += std::string(le.rbegin(), le.rend());
    }
    writeBytes(path("g.pfm"), bytes);
    RadianceImage image = rl::readPfm(path("g.pfm"));
    ASSERT_EQ(image.width, 1);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.rgb, (std::vector<float>{2.0f, 2.0f, 2.0f, 0.5f, 0.5f, 0.5f}));
}

TEST_F(ImageFiles, TruncatedOrForeignFilesAreRefusedWithThePath) {
    writeBytes(path("short.pfm"), "PF\n2 2\n-1.0\n" + floatBytesLE(1.0f));
    expectErrorMentioning([&] { rl::readPfm(path("short.pfm")); }, {path("short.pfm"), "cannot read PFM", "bytes"});
    writeBytes(path("huge.pfm"), "PF\n100000 100000\n-1.0\n");
    expectErrorMentioning([&] { rl::readPfm(path("huge.pfm")); }, {path("huge.pfm"), "cannot read PFM"});
    writeBytes(path("p6.pfm"), "P6\n1 1\n255\nabc");
    expectErrorMentioning([&] { rl::readPfm(path("p6.pfm")); }, {path("p6.pfm"), "not a PFM"});
    writeBytes(path("text.png"), "this is not a PNG");
    expectErrorMentioning([&] { rl::readPng(path("text.png")); }, {path("text.png"), "cannot read PNG"});
}

TEST_F(ImageFiles, WritingIntoAMissingDirectoryThrowsNamingThePath) {
    std::string png = path("no/such/dir/out.png");
    std::string pfm = path("no/such/dir/out.pfm");
    expectErrorMentioning([&] { rl::writePng(png, display(1, 1)); }, {png, "cannot write PNG", "No such file"});
    expectErrorMentioning([&] { rl::writePfm(pfm, RadianceImage{1, 1, {0, 0, 0}}); },
                          {pfm, "cannot write PFM", "No such file"});
    expectErrorMentioning([&] { rl::readPng(png); }, {png, "cannot read PNG"});
    EXPECT_FALSE(fs::exists(png));
}

TEST_F(ImageFiles, MalformedImagesAreNotWritten) {
    expectErrorMentioning([&] { rl::writePng(path("e.png"), DisplayImage{}); }, {path("e.png"), "empty"});
    expectErrorMentioning([&] { rl::writePfm(path("m.pfm"), RadianceImage{2, 2, {1, 2, 3}}); },
                          {path("m.pfm"), "needs 12"});
}

// ---- quantize8 ---------------------------------------------------------------

TEST(Quantize8, ClampsAndRoundsToNearest) {
    EXPECT_EQ(rl::quantize8(0.0), 0);
    EXPECT_EQ(rl::quantize8(1.0), 255);
    EXPECT_EQ(rl::quantize8(-0.25), 0);
    EXPECT_EQ(rl::quantize8(-0.0), 0);
    EXPECT_EQ(rl::quantize8(1.5), 255);
    EXPECT_EQ(rl::quantize8(std::numeric_limits<double>::infinity()), 255);
    EXPECT_EQ(rl::quantize8(-std::numeric_limits<double>::infinity()), 0);
    EXPECT_EQ(rl::quantize8(std::numeric_limits<double>::quiet_NaN()), 0);
    EXPECT_EQ(rl::quantize8(0.5), 128);  // 127.5: halves round up
}

TEST(Quantize8, SwitchesExactlyHalfAnLsbAwayFromEachLevel) {
    const double halfLsb = 0.5 / 255.0;
    const double nudge = 1e-9;  // far above double rounding near 1, far below 1/255
    EXPECT_EQ(rl::quantize8(halfLsb - nudge), 0);
    EXPECT_EQ(rl::quantize8(halfLsb + nudge), 1);
    EXPECT_EQ(rl::quantize8(1.0 - halfLsb - nudge), 254);
    EXPECT_EQ(rl::quantize8(1.0 - halfLsb + nudge), 255);
    for (int k = 0; k <= 255; ++k) {
        EXPECT_EQ(rl::quantize8(k / 255.0), k);
        EXPECT_EQ(rl::quantize8(float(k / 255.0)), k) << "float input, as the GL path reads back";
    }
}

// ---- compareRenderings ---------------------------------------------------------

TEST(CompareRenderings, IdenticalRenderingsHaveNoDifference) {
    Rendering r{RadianceImage{2, 1, {0.1f, 0.2f, 0.3f, 1.0f, 2.0f, 3.0f}}, display(2, 1, 77)};
    rl::ImageDiff d = rl::compareRenderings(r, r);
    EXPECT_EQ(d.offFraction, 0);
    EXPECT_EQ(d.meanLsb, 0);
    EXPECT_EQ(d.p99Lsb, 0);
    EXPECT_EQ(d.maxLsb, 0);
    EXPECT_EQ(d.pfmMedianRel, 0);
    EXPECT_EQ(d.relMse, 0);
    EXPECT_TRUE(std::isinf(d.psnr) && d.psnr > 0);
    EXPECT_EQ(d.nonFinite, 0);
}

TEST(CompareRenderings, EightBitMetricsOnFourPixels) {
    // Pixel 0 equal; pixel 1 one channel off by 1 (within tolerance);
    // pixel 2 one channel off by 2; pixel 3 two channels off by 10.
    Rendering expected{{}, display(2, 2, 100)};
    Rendering got = expected;
    got.display.rgb[3 * 1 + 0] = 101;
    got.display.rgb[3 * 2 + 1] = 98;
    got.display.rgb[3 * 3 + 0] = 110;
    got.display.rgb[3 * 3 + 2] = 90;
    rl::ImageDiff d = rl::compareRenderings(got, expected);
    EXPECT_DOUBLE_EQ(d.offFraction, 2.0 / 4.0);  // pixels 2 and 3 are off by more than 1
    EXPECT_DOUBLE_EQ(d.meanLsb, (1 + 2 + 10 + 10) / 12.0);
    EXPECT_EQ(d.maxLsb, 10);
    EXPECT_DOUBLE_EQ(d.p99Lsb, 10);  // nearest rank ceil(0.99 * 4) = 4: the largest
    double mse = (1 + 4 + 100 + 100) / 12.0;
    EXPECT_NEAR(d.psnr, 10 * std::log10(255.0 * 255.0 / mse), 1e-12);
    EXPECT_EQ(d.pfmMedianRel, 0);  // no radiance in either
    EXPECT_EQ(d.nonFinite, 0);
}

TEST(CompareRenderings, P99IsTheNearestRankOfPerPixelMaxima) {
    Rendering expected{{}, display(10, 10, 0)};
    Rendering got = expected;
    got.display.rgb[0] = 50;  // one pixel in 100: below the 99th percentile
    EXPECT_EQ(rl::compareRenderings(got, expected).p99Lsb, 0);
    got.display.rgb[3] = 30;  // two pixels in 100: the 99th value is now the smaller of them
    EXPECT_EQ(rl::compareRenderings(got, expected).p99Lsb, 30);
    EXPECT_EQ(rl::compareRenderings(got, expected).maxLsb, 50);
}

TEST(CompareRenderings, RadianceMetricsUseTheFlooredRelativeDifference) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Rendering got{RadianceImage{2, 1, {1.1f, 2.2f, 0.0f, 0.001f, 3.0f, nan}}, display(2, 1)};
    Rendering expected{RadianceImage{2, 1, {1.0f, 2.0f, 0.0f, 0.0f, 3.3f, 1.0f}}, display(2, 1)};
    rl::ImageDiff d = rl::compareRenderings(got, expected);
    EXPECT_EQ(d.nonFinite, 1);  // the NaN is counted, and left out of the statistics below
    auto a = [&](int k) { return double(got.radiance.rgb[k]); };
    auto b = [&](int k) { return double(expected.radiance.rgb[k]); };
    auto rel = [&](int k) { return std::abs(a(k) - b(k)) / (std::abs(b(k)) + 1e-3); };
    // The five finite relative differences, sorted: 0 (exact), 0.3/3.301,
    // 0.1/1.001, 0.2/2.001, 1 (0.001 on black: absolute in units of 1e-3).
    EXPECT_LT(rel(4), rel(0));
    EXPECT_LT(rel(0), rel(1));
    EXPECT_NEAR(rel(3), 1.0, 1e-6);
    EXPECT_DOUBLE_EQ(d.pfmMedianRel, rel(0));
    double relMse = 0;
    for (int k : {0, 1, 2, 3, 4}) relMse += (a(k) - b(k)) * (a(k) - b(k)) / (b(k) * b(k) + 1e-2);
    EXPECT_NEAR(d.relMse, relMse / 5, 1e-15);
}

TEST(CompareRenderings, MedianOfAnEvenCountAveragesTheMiddlePair) {
    Rendering got{RadianceImage{2, 1, {1.0f, 1.0f, 1.0f, 2.0f, 2.0f, 2.0f}}, display(2, 1)};
    Rendering expected{RadianceImage{2, 1, {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f}}, display(2, 1)};
    // Relative differences 0, 0, 0, r, r, r with r = 1/1.001: the middle pair is (0, r).
    EXPECT_DOUBLE_EQ(rl::compareRenderings(got, expected).pfmMedianRel, 0.5 / 1.001);
}

TEST(CompareRenderings, DifferentSizesAreAnError) {
    Rendering a{{}, display(2, 1)}, b{{}, display(1, 2)};
    expectErrorMentioning([&] { rl::compareRenderings(a, b); }, {"2x1", "1x2"});
    Rendering c{RadianceImage{2, 1, std::vector<float>(6)}, display(2, 1)};
    Rendering e{RadianceImage{1, 1, std::vector<float>(3)}, display(2, 1)};
    expectErrorMentioning([&] { rl::compareRenderings(c, e); }, {"radiance"});
}

// ---- differenceHeatMap ---------------------------------------------------------

TEST(DifferenceHeatMap, BlackWhereEqualRedHalfWayYellowFromEightLsb) {
    DisplayImage expected = display(5, 1, 100);
    DisplayImage got = expected;
    got.at(1, 0)[0] = 101;  // 1 LSB: dim red
    got.at(2, 0)[2] = 96;   // 4 LSB: full red
    got.at(3, 0)[1] = 108;  // 8 LSB: yellow
    got.at(4, 0)[0] = 0;    // 100 LSB: still yellow
    DisplayImage map = rl::differenceHeatMap(got, expected);
    ASSERT_EQ(map.width, 5);
    ASSERT_EQ(map.height, 1);
    auto pixel = [&](int x) { return std::vector<int>(map.at(x, 0), map.at(x, 0) + 3); };
    EXPECT_EQ(pixel(0), (std::vector<int>{0, 0, 0}));
    EXPECT_EQ(pixel(1), (std::vector<int>{64, 0, 0}));
    EXPECT_EQ(pixel(2), (std::vector<int>{255, 0, 0}));
    EXPECT_EQ(pixel(3), (std::vector<int>{255, 255, 0}));
    EXPECT_EQ(pixel(4), (std::vector<int>{255, 255, 0}));
}
