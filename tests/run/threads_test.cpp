// How many threads a run uses (run/threads.hpp): the front end's choice, HYDRODDA_THREADS, or
// the machine's; bad values are refused naming the variable.

#include "run/threads.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <optional>
#include <string>

#include "numerics/parallel.hpp"
#include "run/run.hpp"

namespace hydrodda::run {
namespace {

// HYDRODDA_THREADS set (or unset) for one test, and put back.
class ThreadsVariable {
 public:
  explicit ThreadsVariable(const char* value) {
    if (const char* before = std::getenv(kThreadsVariable)) before_ = before;
    if (value)
      ::setenv(kThreadsVariable, value, 1);
    else
      ::unsetenv(kThreadsVariable);
  }
  ~ThreadsVariable() {
    if (before_)
      ::setenv(kThreadsVariable, before_->c_str(), 1);
    else
      ::unsetenv(kThreadsVariable);
  }

 private:
  std::optional<std::string> before_;
};

TEST(Threads, CountsAreWholeNumbersFromOneTo4096) {
  EXPECT_EQ(parse_thread_count("1"), 1);
  EXPECT_EQ(parse_thread_count("8"), 8);
  EXPECT_EQ(parse_thread_count("4096"), 4096);
  for (const char* bad : {"", "0", "-1", "+2", "2.0", "2 ", " 2", "two", "4097", "99999999999", "0x10"})
    EXPECT_EQ(parse_thread_count(bad), std::nullopt) << "'" << bad << "'";
}

TEST(Threads, TheFrontEndsChoiceComesFirstThenTheVariable) {
  {
    const ThreadsVariable variable("3");
    EXPECT_EQ(chosen_thread_count(std::nullopt), 3);
    EXPECT_EQ(chosen_thread_count(5), 5);
  }
  {
    const ThreadsVariable unset(nullptr);
    EXPECT_EQ(chosen_thread_count(std::nullopt), std::nullopt);
    EXPECT_EQ(chosen_thread_count(2), 2);
  }
}

// The default count is the cores the load average leaves free (the cores less the load,
// rounded), never fewer than one: threads that outnumber the free cores wait on each other.
TEST(Threads, TheDefaultTakesTheCoresTheLoadLeavesFree) {
  EXPECT_EQ(cores_left_free(2, 0.0), 2);
  EXPECT_EQ(cores_left_free(2, 0.49), 2);
  EXPECT_EQ(cores_left_free(2, 0.5), 1);
  EXPECT_EQ(cores_left_free(2, 1.49), 1);
  EXPECT_EQ(cores_left_free(2, 13.0), 1);
  EXPECT_EQ(cores_left_free(64, 10.2), 54);
  EXPECT_EQ(cores_left_free(64, 1e300), 1);
  EXPECT_EQ(cores_left_free(8, std::nan("")), 8);
}

TEST(Threads, ABadVariableIsNamedWithItsValue) {
  const ThreadsVariable variable("lots");
  try {
    chosen_thread_count(std::nullopt);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("HYDRODDA_THREADS"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'lots'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(chosen_thread_count(4), 4);  // the front end's choice does not read it
}

TEST(Threads, ACallsOwnCountHoldsOnItsThreadWhileItLasts) {
  const ThreadsVariable unset(nullptr);
  const int before = numerics::thread_count();
  {
    const ThreadsOfThisCall call(7);
    EXPECT_EQ(numerics::thread_count(), 7);
  }
  EXPECT_EQ(numerics::thread_count(), before);
  {
    const ThreadsOfThisCall call(std::nullopt);  // nothing chosen: the process's
    EXPECT_EQ(numerics::thread_count(), before);
  }
}

}  // namespace
}  // namespace hydrodda::run
