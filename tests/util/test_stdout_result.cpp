// util/stdout_result: which output names mean standard output, and "-" refused where a file is
// needed.
#include <gtest/gtest.h>

#include "util/error.hpp"
#include "util/output_file.hpp"
#include "util/stdout_result.hpp"

using namespace zc;

TEST(StdoutResult, DashAndTheDevicesNameStandardOutput) {
  for (const char* p : {"-", "/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"})
    EXPECT_TRUE(names_stdout(p)) << p;
  for (const char* p : {"", "--", "report.json", "/dev/stderr", "./-"})
    EXPECT_FALSE(names_stdout(p)) << p;
}

TEST(StdoutResult, DashIsNoFileName) {
  EXPECT_THROW(check_output_path("-", "--image"), UsageError);
}
