// core/NumberInput: what every number from a user passes.
#include "core/Error.h"
#include "core/NumberInput.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace lenslab {
namespace {

const NumberRange kSeconds{.min = 0.0, .max = 10.0, .unit = "seconds"};

TEST(NumberInput, RefusesWhatIsNotFinite) {
  for (const char* text : {"nan", "-nan", "inf", "-inf", "infinity", "1e309", "-1e309"}) {
    const auto problem = numberTextProblem(text, kSeconds);
    ASSERT_TRUE(problem) << text;
    EXPECT_NE(problem->find("not a finite number of seconds"), std::string::npos) << *problem;
  }
  EXPECT_TRUE(numberProblem(std::numeric_limits<double>::quiet_NaN(), kSeconds));
}

TEST(NumberInput, RefusesOutOfRangeAndNonNumbers) {
  EXPECT_TRUE(numberTextProblem("10.5", kSeconds));
  EXPECT_TRUE(numberTextProblem("-1", kSeconds));
  EXPECT_TRUE(numberTextProblem("3s", kSeconds));
  EXPECT_TRUE(numberTextProblem("", kSeconds));
  EXPECT_FALSE(numberTextProblem("0", kSeconds));
  EXPECT_FALSE(numberTextProblem("+2.5", kSeconds));
  EXPECT_DOUBLE_EQ(readNumber("--time", "2.5", kSeconds), 2.5);
}

TEST(NumberInput, MessageNamesTheFieldAndQuotesLittle) {
  try {
    readNumber("--time", std::string(100000, '9'), kSeconds);
    FAIL() << "not refused";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("--time: ", 0), 0u) << message;
    EXPECT_LT(message.size(), 200u) << message;
    EXPECT_NE(message.find("…"), std::string::npos) << message;
  }
  EXPECT_THROW(checkedNumber("fx", std::numeric_limits<double>::infinity(), {.min = 0.0}), InputError);
}

}  // namespace
}  // namespace lenslab
