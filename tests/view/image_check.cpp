// A small image checker for the view's scripted tests (tests/view/view_test.sh).
//   image_check psnr A B MIN_DB           exit 0 when PSNR(A, B) >= MIN_DB (display-encoded, as
//                                         an 8-bit screen shows them), printing the figure
//   image_check busy IMG X0 Y0 X1 Y1 MIN   exit 0 when the region [X0, X1) × [Y0, Y1) holds
//                                         non-trivial content: the standard deviation of its
//                                         luminance (display-encoded) is at least MIN
//   image_check count IMG R G B TOL        prints how many pixels are within TOL of the display-
//                                         encoded colour (R, G, B) in [0, 1] in every channel
// Exit 1 on a failed check, 2 on bad usage or unreadable files.
#include "io/ImageCompare.h"
#include "io/ImageFile.h"

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

using namespace lenslab;

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "psnr" && argc == 5) {
      const Image a = displayEncoded(readImage(argv[2])), b = displayEncoded(readImage(argv[3]));
      const ImageDifference d = compareImages(a, b, 3.0 / 255.0);
      const double minimum = std::atof(argv[4]);
      std::cout << "psnr " << d.psnrDb << " dB (max abs " << d.maxAbs << ", minimum " << minimum << " dB)\n";
      return d.psnrDb >= minimum ? 0 : 1;
    }
    if (mode == "busy" && argc == 8) {
      const Image image = displayEncoded(readImage(argv[2]));
      const int x0 = std::atoi(argv[3]), y0 = std::atoi(argv[4]), x1 = std::atoi(argv[5]), y1 = std::atoi(argv[6]);
      if (x0 < 0 || y0 < 0 || x1 > image.width || y1 > image.height || x0 >= x1 || y0 >= y1) {
        std::cerr << "image_check: region outside the " << image.width << "x" << image.height << " image\n";
        return 2;
      }
      double sum = 0.0, sumSquares = 0.0;
      for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
          const glm::vec4 c = image.at(x, y);
          const double l = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
          sum += l;
          sumSquares += l * l;
        }
      }
      const double n = static_cast<double>(x1 - x0) * (y1 - y0);
      const double deviation = std::sqrt(std::max(0.0, sumSquares / n - (sum / n) * (sum / n)));
      const double minimum = std::atof(argv[7]);
      std::cout << "luminance deviation " << deviation << " (minimum " << minimum << ")\n";
      return deviation >= minimum ? 0 : 1;
    }
    if (mode == "count" && argc == 7) {
      const Image image = displayEncoded(readImage(argv[2]));
      const glm::vec3 colour(std::atof(argv[3]), std::atof(argv[4]), std::atof(argv[5]));
      const float tolerance = static_cast<float>(std::atof(argv[6]));
      long count = 0;
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
          const glm::vec4 c = image.at(x, y);
          const glm::vec3 d = glm::abs(glm::vec3(c) - colour);
          if (d.r <= tolerance && d.g <= tolerance && d.b <= tolerance) ++count;
        }
      std::cout << count << "\n";
      return 0;
    }
    std::cerr
        << "usage: image_check psnr A B MIN_DB | image_check busy IMG X0 Y0 X1 Y1 MIN | image_check count IMG R G "
           "B TOL\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "image_check: " << e.what() << "\n";
    return 2;
  }
}
