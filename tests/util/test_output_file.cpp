// util/output_file: an output that would block (a FIFO) is refused before any work, and a write to
// a device that fails (/dev/full, directly or through a link) is an error, never lost.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "util/error.hpp"
#include "util/output_file.hpp"

namespace zc {
namespace {

namespace fs = std::filesystem;

class OutputScratchDir {
public:
  OutputScratchDir() {
    std::string t = (fs::temp_directory_path() / "zcube-test-output-XXXXXX").string();
    path_ = ::mkdtemp(t.data()) ? t : "";
  }
  ~OutputScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string operator/(const std::string& name) const { return (fs::path(path_) / name).string(); }

private:
  std::string path_;
};

TEST(OutputFile, AFifoIsRefusedBeforeAnyWork) {
  const OutputScratchDir dir;
  for (const std::string name : {"f.png", "f.json", "f.xml"}) {
    const std::string fifo = dir / name;
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    try {
      check_output_path(fifo, "--image");
      ADD_FAILURE() << name << ": accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--image '" + fifo + "': is a FIFO"), std::string::npos)
          << e.what();
    }
    // A link to it too.
    const std::string link = dir / ("link-" + name);
    fs::create_symlink(fifo, link);
    EXPECT_THROW(check_output_path(link, "--report"), UsageError);
    EXPECT_THROW(write_text_file(link, "x"), std::runtime_error);
  }
}

TEST(OutputFile, AFullDeviceIsAnErrorThroughALinkOrNot) {
  if (::access("/dev/full", W_OK) != 0) GTEST_SKIP() << "no writable /dev/full";
  const OutputScratchDir dir;
  const std::string link = dir / "out.png";
  fs::create_symlink("/dev/full", link);
  EXPECT_NO_THROW(check_output_path(link, "--image")); // a device is written in place
  for (const std::string& path : {std::string("/dev/full"), link}) {
    SCOPED_TRACE(path);
    try {
      write_file_atomically(path, [](const std::string& tmp) {
        std::ofstream(tmp) << std::string(100000, 'x'); // a writer that checks nothing
        return true;
      });
      ADD_FAILURE() << "the failed write was lost";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_THROW(write_text_file(path, "text"), std::runtime_error);
  }
  EXPECT_TRUE(fs::is_symlink(link)); // the link is kept
}

TEST(OutputFile, AWriterThatReusesThePathStringStillWritesTheTarget) {
  // The Gantt writer hands each chart's temporary name on through the string it passed as the
  // path: the device is still the one written.
  if (::access("/dev/full", W_OK) != 0) GTEST_SKIP() << "no writable /dev/full";
  const OutputScratchDir dir;
  std::string path = dir / "chart.png";
  fs::create_symlink("/dev/full", path);
  EXPECT_THROW(write_file_atomically(path,
                                     [&](const std::string& tmp) {
                                       path = tmp;
                                       std::ofstream(tmp) << "picture";
                                       return true;
                                     }),
               std::runtime_error);
}

TEST(OutputFile, ADeviceThatTakesTheBytesGetsThemAll) {
  EXPECT_NO_THROW(write_text_file("/dev/null", std::string(200000, 'y')));
}

} // namespace
} // namespace zc
