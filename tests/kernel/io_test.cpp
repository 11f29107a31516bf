// The file input and output behind plot, record, output csv and output movie,
// without Tcl: the CSV reader and writer, gnuplot's quoting and script,
// finding and running programs, the ffmpeg pipe (stand-in programs on a fake
// PATH, so that neither gnuplot nor ffmpeg is needed).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sandflow/core/error.hpp"
#include "sandflow/io/csv_table.hpp"
#include "sandflow/io/csv_writer.hpp"
#include "sandflow/io/ffmpeg_pipe.hpp"
#include "sandflow/io/find_program.hpp"
#include "sandflow/io/gnuplot.hpp"
#include "sandflow/io/run_program.hpp"

namespace fs = std::filesystem;
using sf::Error;

namespace {

// A fresh folder per test, removed afterwards; PATH is restored too.
class IoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = (fs::temp_directory_path() / "sandflow_io_XXXXXX").string();
    ASSERT_NE(::mkdtemp(name.data()), nullptr);
    dir_ = name;
    const char* path = std::getenv("PATH");
    savedPath_ = path ? path : "";
  }
  void TearDown() override {
    ::setenv("PATH", savedPath_.c_str(), 1);
    fs::remove_all(dir_);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  void write(const std::string& name, const std::string& text, bool executable = false) const {
    std::ofstream(file(name), std::ios::binary) << text;
    if (executable) fs::permissions(file(name), fs::perms::owner_all);
  }
  std::string read(const std::string& name) const {
    std::ifstream in(file(name), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  // The files in the folder, sorted.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }
  // Puts a program `name` with this shell text in DIR/bin, first on the PATH.
  std::string fakeProgram(const std::string& name, const std::string& body) {
    fs::create_directories(dir_ / "bin");
    write("bin/" + name, "#!/bin/sh\n" + body + "\n", true);
    ::setenv("PATH", (file("bin") + ":" + savedPath_).c_str(), 1);
    return file("bin/" + name);
  }
  fs::path dir_;
  std::string savedPath_;
};

template <class Body>
Error errorOf(Body&& body) {
  try {
    body();
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no sf::Error thrown";
  return Error("NONE", "");
}

// ---- CSV reader ----------------------------------------------------------

TEST_F(IoTest, CsvReaderKeepsHeaderRowsAndTheirLines) {
  write("a.csv", "step, time ,x\n\n0,0,1.5\r\n  \n1,0.1, -2e3 \n");
  const sf::io::CsvTable csv = sf::io::readCsv(file("a.csv"));
  EXPECT_EQ(csv.names, (std::vector<std::string>{"step", "time", "x"}));
  ASSERT_EQ(csv.rows.size(), 2u);
  EXPECT_EQ(csv.rows[0], (std::vector<std::string>{"0", "0", "1.5"}));
  EXPECT_EQ(csv.rows[1], (std::vector<std::string>{"1", "0.1", "-2e3"}));
  EXPECT_EQ(csv.lines, (std::vector<int>{3, 5}));  // blank lines count, are skipped
  EXPECT_EQ(sf::io::columnIndex(csv, "x"), 2);
}

TEST_F(IoTest, CsvReaderNamesTheLineOfAMalformedRow) {
  write("a.csv", "a,b,c\n1,2,3\n\n4,5\n");
  const Error e = errorOf([&] { sf::io::readCsv(file("a.csv")); });
  EXPECT_EQ(e.code(), "VALUE CSV");
  EXPECT_EQ(std::string(e.what()),
            "line 4 of \"" + file("a.csv") + "\" has 2 values, the header 3 columns");
}

TEST_F(IoTest, CsvReaderRefusesMissingEmptyAndHeaderOnlyFiles) {
  EXPECT_EQ(errorOf([&] { sf::io::readCsv(file("none.csv")); }).code(), "IO OPEN");
  write("empty.csv", "\n \n");
  EXPECT_EQ(std::string(errorOf([&] { sf::io::readCsv(file("empty.csv")); }).what()),
            "\"" + file("empty.csv") + "\" is empty: no header line");
  write("header.csv", "a,b\n");
  EXPECT_EQ(std::string(errorOf([&] { sf::io::readCsv(file("header.csv")); }).what()),
            "\"" + file("header.csv") + "\" has a header but no data rows");
}

TEST_F(IoTest, UnknownColumnListsTheColumnsAndNamesAnotherFile) {
  write("a.csv", "h,err,gap\n1,2,3\n");
  const sf::io::CsvTable csv = sf::io::readCsv(file("a.csv"));
  const Error e = errorOf([&] { sf::io::columnIndex(csv, "q"); });
  EXPECT_EQ(e.code(), "LOOKUP COLUMN");
  EXPECT_EQ(std::string(e.what()), "bad column \"q\": must be h, err, or gap");
  EXPECT_EQ(std::string(errorOf([&] { sf::io::columnIndex(csv, "q", "b.csv", "a.csv"); }).what()),
            "bad column \"q\" in \"b.csv\": must be h, err, or gap");
  EXPECT_EQ(std::string(errorOf([&] { sf::io::columnIndex(csv, "q", "a.csv", "a.csv"); }).what()),
            "bad column \"q\": must be h, err, or gap");
}

// ---- CSV writer ----------------------------------------------------------

TEST_F(IoTest, CsvWriterWritesHeaderAndFullPrecisionRows) {
  sf::io::CsvWriter w(file("s.csv"), {"a", "b"});
  EXPECT_FALSE(w.isOpen());
  w.write(0, 0.0, {0.1 + 0.2, 1e-300});
  EXPECT_EQ(read("s.csv"), "step,time,a,b\n0,0,0.30000000000000004,1e-300\n");  // flushed
  w.write(10, 0.5, {-1, 2});
  w.close();
  EXPECT_EQ(read("s.csv"), "step,time,a,b\n0,0,0.30000000000000004,1e-300\n10,0.5,-1,2\n");
}

TEST_F(IoTest, CsvWriterResumesAtAStepDroppingTheRowsFromIt) {
  {
    sf::io::CsvWriter w(file("s.csv"), {"a"});
    for (int step = 0; step <= 40; step += 10) w.write(step, step / 10.0, {double(step)});
    w.close();
  }
  sf::io::CsvWriter w(file("s.csv"), {"a"});
  w.write(20, 2, {-20}, 20);  // the checkpoint was taken at step 20
  w.write(30, 3, {-30}, 20);  // (only the first write resumes)
  w.close();
  EXPECT_EQ(read("s.csv"), "step,time,a\n0,0,0\n10,1,10\n20,2,-20\n30,3,-30\n");
}

TEST_F(IoTest, CsvWriterStartsAfreshWhenTheFileIsAnotherSeries) {
  write("s.csv", "step,time,other\n0,0,1\n");
  sf::io::CsvWriter w(file("s.csv"), {"a"});
  w.write(5, 1, {2}, 5);
  w.close();
  EXPECT_EQ(read("s.csv"), "step,time,a\n5,1,2\n");
}

TEST_F(IoTest, CsvWriterThatCannotOpenLeavesNoFile) {
  sf::io::CsvWriter w(file("missing/s.csv"), {"a"});
  const Error e = errorOf([&] { w.write(0, 0, {1}); });
  EXPECT_EQ(e.code(), "IO OPEN");
  EXPECT_EQ(std::string(e.what()).rfind("cannot open it for writing: ", 0), 0u);
  EXPECT_FALSE(w.isOpen());
}

// ---- gnuplot ------------------------------------------------------------

TEST(Gnuplot, StringsQuoteQuotesBackslashesAndLineBreaks) {
  using sf::io::gnuplotString;
  EXPECT_EQ(gnuplotString(""), "''");
  EXPECT_EQ(gnuplotString("plain"), "'plain'");
  // Inside single quotes a backslash, a backquote, @ and $ are plain text.
  EXPECT_EQ(gnuplotString("a\\b `x` @y $z"), "'a\\b `x` @y $z'");
  EXPECT_EQ(gnuplotString("it's"), "'it'.\"'\".'s'");
  EXPECT_EQ(gnuplotString("'"), "\"'\"");
  EXPECT_EQ(gnuplotString("''"), "\"'\".\"'\"");
  EXPECT_EQ(gnuplotString("one\ntwo"), "'one'.\"\\n\".'two'");
  EXPECT_EQ(gnuplotString("tab\there"), "'tab here'");
}

TEST_F(IoTest, GnuplotScriptQuotesTextAndChecksValues) {
  write("a.csv", "time,y\n0,1\n1,4\n");
  const sf::io::CsvTable csv = sf::io::readCsv(file("a.csv"));
  sf::io::PlotOptions o;
  o.title = "Bob's \\plot";
  const std::vector<sf::io::PlotSeries> series = {{&csv, "a.csv", 0, 1, "y", 0, 0, 0}};
  const std::string script = sf::io::gnuplotScript(series, "time", o, "/tmp/o'ut.png");
  EXPECT_NE(script.find("set output '/tmp/o'.\"'\".'ut.png'\n"), std::string::npos);
  EXPECT_NE(script.find("set title 'Bob'.\"'\".'s \\plot' noenhanced\n"), std::string::npos);
  EXPECT_NE(script.find("$d0 << EOD\n0 1\n1 4\nEOD\n"), std::string::npos);
  o.logy = true;
  write("b.csv", "time,y\n0,1\n1,0\n");
  const sf::io::CsvTable zero = sf::io::readCsv(file("b.csv"));
  const Error e = errorOf([&] {
    sf::io::gnuplotScript({{&zero, "b.csv", 0, 1, "y", 0, 0, 0}}, "time", o, "o.png");
  });
  EXPECT_EQ(e.code(), "VALUE LOG");
  EXPECT_EQ(std::string(e.what()),
            "-logy needs values > 0, but column \"y\", line 3 of \"b.csv\" is 0 (gnuplot would "
            "leave it out)");
}

TEST_F(IoTest, GnuplotScriptGivesASeriesItsColourMarkAndSize) {
  write("a.csv", "x,y\n1,2\n3,4\n");
  const sf::io::CsvTable csv = sf::io::readCsv(file("a.csv"));
  sf::io::PlotOptions o;
  o.key = 5;  // outside
  std::vector<sf::io::PlotSeries> series = {{&csv, "a.csv", 0, 1, "ok", 1, 0, 0},
                                            {&csv, "a.csv", 0, 1, "bad", 1, 0, 0}};
  series[0].color = 1;  // green
  series[0].mark = 4;   // diamond
  series[0].marksize = 2.5;
  series[1].mark = 10;  // cross, the colour by order
  const std::string script = sf::io::gnuplotScript(series, "x", o, "o.png");
  EXPECT_NE(script.find("set key outside right top box\n"), std::string::npos);
  EXPECT_NE(script.find("$d0 using 1:2 with points pt 13 ps 2.5 lc rgb '#2ca02c' title 'ok'"),
            std::string::npos);
  EXPECT_NE(script.find("$d1 using 1:2 with points pt 2 ps 1.2 title 'bad'"), std::string::npos);
  EXPECT_EQ(std::string(sf::io::kPlotColors[1]), "green");
  EXPECT_EQ(std::string(sf::io::kPlotMarks[10]), "cross");
}

TEST_F(IoTest, PlotIsRenamedIntoPlaceOnlyWhenGnuplotSucceeds) {
  write("a.csv", "step,time,y\n0,0,1\n1,1,2\n");
  // A stand-in that keeps the script and writes a placeholder to its output.
  const std::string good =
      fakeProgram("gnuplot", "cat > '" + file("script.gp") +
                                 "'\nout=$(sed -n \"s/^set output '\\(.*\\)'$/\\1/p\" '" +
                                 file("script.gp") + "')\nprintf image > \"$out\"");
  std::vector<std::string> asked;
  sf::io::plotCsv(good, file("p.png"), file("a.csv"), {},
                  [&](const std::string& f) { asked.push_back(f); });
  EXPECT_EQ(read("p.png"), "image");
  EXPECT_TRUE(asked.empty());  // no -series file
  EXPECT_EQ(files(), (std::vector<std::string>{"a.csv", "bin", "p.png", "script.gp"}));
  const std::string bad = fakeProgram("gnuplot", "echo 'line 9: something broke' >&2\nexit 1");
  const Error e =
      errorOf([&] { sf::io::plotCsv(bad, file("q.png"), file("a.csv"), {}, [](auto&) {}); });
  EXPECT_EQ(e.code(), "IO GNUPLOT");
  EXPECT_EQ(std::string(e.what()),
            "gnuplot failed: line 9: something broke\nchild process exited abnormally");
  EXPECT_EQ(files(), (std::vector<std::string>{"a.csv", "bin", "p.png", "script.gp"}));
}

// ---- programs ------------------------------------------------------------

TEST_F(IoTest, FindProgramTakesTheFirstExecutableRegularFileOnThePath) {
  fs::create_directories(dir_ / "a/prog");  // a folder: not a program
  fs::create_directories(dir_ / "b");
  write("b/prog", "#!/bin/sh\n");  // not executable
  fs::create_directories(dir_ / "c");
  write("c/prog", "#!/bin/sh\n", true);
  fs::create_directories(dir_ / "d");
  write("d/prog", "#!/bin/sh\n", true);
  ::setenv("PATH", (file("a") + ":" + file("b") + ":" + file("c") + ":" + file("d")).c_str(), 1);
  EXPECT_EQ(sf::io::findProgram("prog"), file("c") + "/prog");
  EXPECT_EQ(sf::io::findProgram("nothing"), "");
  ::setenv("PATH", file("a").c_str(), 1);
  EXPECT_EQ(sf::io::findProgram("prog"), "");
}

TEST_F(IoTest, RunProgramGivesInputAndCapturesBothOutputs) {
  const std::string prog = fakeProgram("p", "read line\necho \"got $line\"\necho oops >&2");
  const sf::io::ProgramRun ok = sf::io::runProgram({prog}, "hello\n");
  EXPECT_TRUE(ok.ok);
  EXPECT_EQ(ok.output, "got hello\noops");
  const std::string quiet = fakeProgram("q", "exit 3");  // reads none of its input
  const sf::io::ProgramRun failed = sf::io::runProgram({quiet}, std::string(1 << 20, 'x'));
  EXPECT_FALSE(failed.ok);
  EXPECT_EQ(failed.output, "child process exited abnormally");
  const sf::io::ProgramRun missing = sf::io::runProgram({file("none")}, "");
  EXPECT_FALSE(missing.ok);
  EXPECT_EQ(missing.output.rfind("couldn't execute \"" + file("none") + "\": ", 0), 0u);
}

// ---- ffmpeg pipe ---------------------------------------------------------

TEST(FfmpegPipe, MovieFilesAreKnownContainers) {
  EXPECT_TRUE(sf::io::isMovieFile("a.mp4"));
  EXPECT_TRUE(sf::io::isMovieFile("dir.x/A.WebM"));
  EXPECT_FALSE(sf::io::isMovieFile("a.gif"));
  EXPECT_FALSE(sf::io::isMovieFile("a.mp4/b"));
}

TEST_F(IoTest, FfmpegPipeRenamesAFinishedMovieIntoPlace) {
  // Takes the frames and writes them to its last argument, the part file.
  const std::string ffmpeg = fakeProgram("ffmpeg", "for a; do out=$a; done\ncat > \"$out\"");
  {
    sf::io::FfmpegPipe movie(ffmpeg, file("m.mp4"), 2, 1, 25);
    const std::uint8_t frame[8] = {'f', 'r', 'a', 'm', 'e', '.', '.', '\n'};
    movie.writeFrame(frame, sizeof frame);
    movie.writeFrame(frame, sizeof frame);
    movie.finish();
  }
  EXPECT_EQ(read("m.mp4"), "frame..\nframe..\n");
  EXPECT_EQ(files(), (std::vector<std::string>{"bin", "m.mp4"}));
}

TEST_F(IoTest, FfmpegPipeReportsFfmpegsMessageAndLeavesNothing) {
  const std::string ffmpeg = fakeProgram("ffmpeg", "echo 'Invalid argument' >&2\nexit 1");
  sf::io::FfmpegPipe movie(ffmpeg, file("m.mp4"), 2, 2, 25);
  const Error e = errorOf([&] { movie.finish(); });
  EXPECT_EQ(e.code(), "IO MOVIE");
  EXPECT_EQ(std::string(e.what()), "ffmpeg failed: Invalid argument");
  EXPECT_EQ(files(), (std::vector<std::string>{"bin"}));
}

TEST_F(IoTest, AnAbandonedMovieLeavesNothing) {
  const std::string ffmpeg = fakeProgram("ffmpeg", "cat > /dev/null");
  { sf::io::FfmpegPipe movie(ffmpeg, file("m.mkv"), 2, 2, 25); }
  EXPECT_EQ(files(), (std::vector<std::string>{"bin"}));
  EXPECT_EQ(errorOf([&] { sf::io::FfmpegPipe(ffmpeg, file("none/m.mkv"), 2, 2, 25); }).code(),
            "IO MOVIE");
}

}  // namespace
