// Only regular files (after following links) are read as decks or includes (issue 38): a device, a
// named pipe, a socket or a directory is DK010 at the *INCLUDE or #include line, or exit 2 with a plain
// message as the deck itself, and nothing blocks (a pipe opened for reading waits for a writer; the
// runs here are bounded by `timeout`, so a regression fails instead of hanging the suite).
#include <doctest/doctest.h>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <string>

#include "text/text_file.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_special_files_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
namespace fs = std::filesystem;

namespace {

// `sphdeck ARGS` in `dir`, killed after 20 s (exit 124): a read that blocks fails the test.
test::Run run_bounded(const test::TempDir& dir, const std::string& args) {
    return test::run_sphdeck(dir, args + " < /dev/null", "timeout -k 5 20 ");
}

// A folder with one special file of each kind: a named pipe, a socket, a directory, and a link to
// the pipe; the character device is /dev/zero.
void make_special_files(const test::TempDir& dir) {
    REQUIRE(::mkfifo((dir.path() / "pipe.k").c_str(), 0600) == 0);
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    REQUIRE(fd >= 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    const std::string socket_path = (dir.path() / "socket.k").string();
    REQUIRE(socket_path.size() < sizeof(address.sun_path));
    std::strncpy(address.sun_path, socket_path.c_str(), sizeof(address.sun_path) - 1);
    REQUIRE(::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) == 0);
    ::close(fd);  // the socket file stays
    fs::create_directories(dir.path() / "folder.k");
    fs::create_symlink("pipe.k", dir.path() / "pipe_link.k");
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("special files: each kind is named by its type, without opening it") {
    test::TempDir dir;
    make_special_files(dir);
    CHECK(text::special_file_kind("/dev/zero") == "a character device");
    CHECK(text::special_file_kind((dir.path() / "pipe.k").string()) == "a named pipe");
    CHECK(text::special_file_kind((dir.path() / "pipe_link.k").string()) == "a named pipe");  // the link followed
    CHECK(text::special_file_kind((dir.path() / "socket.k").string()) == "a socket");
    CHECK(text::special_file_kind((dir.path() / "folder.k").string()) == "a directory");
    CHECK_FALSE(text::special_file_kind(dir.write("deck.k", "*KEYWORD\n")));
    CHECK_FALSE(text::special_file_kind((dir.path() / "missing.k").string()));
    CHECK_THROWS_WITH(text::read_text_file((dir.path() / "socket.k").string()),
                      doctest::Contains("socket.k' is a socket, not a deck file"));
}

TEST_CASE("special files: an LS-DYNA *INCLUDE of a device, a pipe, a socket or a directory is DK010 at its line") {
    test::TempDir dir;
    make_special_files(dir);
    dir.write("main.k",
              "*KEYWORD\n*INCLUDE\n/dev/zero\n*INCLUDE\npipe.k\n*INCLUDE\nsocket.k\n*INCLUDE\nfolder.k\n"
              "*INCLUDE\npipe_link.k\n*END\n");
    const test::Run r = run_bounded(dir, "check --format concise --no-config main.k");
    CHECK(r.exit_code == 1);
    CHECK(has(r.out,
              "main.k:3:1: error: include file '/dev/zero' cannot be read: '/dev/zero' is a character "
              "device, not a deck file [DK010]"));
    CHECK(has(r.out, "main.k:5:1: error: include file 'pipe.k' cannot be read: '"));
    CHECK(has(r.out, "pipe.k' is a named pipe, not a deck file [DK010]"));
    CHECK(has(r.out, "main.k:7:1: error: include file 'socket.k' cannot be read: '"));
    CHECK(has(r.out, "socket.k' is a socket, not a deck file [DK010]"));
    CHECK(has(r.out, "main.k:9:1: error: include file 'folder.k' cannot be read: '"));
    CHECK(has(r.out, "folder.k' is a directory, not a deck file [DK010]"));
    CHECK(has(r.out, "main.k:11:1: error: include file 'pipe_link.k' cannot be read: '"));
    CHECK(has(r.out, "pipe_link.k' is a named pipe, not a deck file [DK010]"));
    CHECK(has(r.err, "checked 1 file(s)"));  // none of them counted as read
}

TEST_CASE("special files: an OpenRadioss #include of a device, a pipe, a socket or a directory is DK010 at its line") {
    test::TempDir dir;
    make_special_files(dir);
    dir.write("m_0000.rad",
              "#RADIOSS STARTER\n/BEGIN\nrun\n      2026         0\n"
              "                  kg                  mm                  ms\n"
              "                  kg                  mm                  ms\n"
              "#include /dev/zero\n#include pipe.k\n#include socket.k\n#include folder.k\n/END\n");
    const test::Run r = run_bounded(dir, "check --format concise --no-config m_0000.rad");
    CHECK(r.exit_code == 1);
    CHECK(has(r.out,
              "m_0000.rad:7:10: error: include file '/dev/zero' cannot be read: '/dev/zero' is a character "
              "device, not a deck file [DK010]"));
    CHECK(has(r.out, "m_0000.rad:8:10: error: include file 'pipe.k' cannot be read: '"));
    CHECK(has(r.out, "pipe.k' is a named pipe, not a deck file [DK010]"));
    CHECK(has(r.out, "m_0000.rad:9:10: error: include file 'socket.k' cannot be read: '"));
    CHECK(has(r.out, "socket.k' is a socket, not a deck file [DK010]"));
    CHECK(has(r.out, "m_0000.rad:10:10: error: include file 'folder.k' cannot be read: '"));
    CHECK(has(r.out, "folder.k' is a directory, not a deck file [DK010]"));
}

TEST_CASE("special files: a device, a pipe or a socket as the deck itself is exit 2 with a plain message") {
    test::TempDir dir;
    make_special_files(dir);
    const std::pair<const char*, const char*> decks[] = {{"/dev/zero", "'/dev/zero' is a character device"},
                                                         {"pipe.k", "'pipe.k' is a named pipe"},
                                                         {"pipe_link.k", "'pipe_link.k' is a named pipe"},
                                                         {"socket.k", "'socket.k' is a socket"}};
    for (const auto& entry : decks) {  // no structured binding: clang cannot capture one in CAPTURE()
        const char* deck = entry.first;
        const char* message = entry.second;
        for (const char* command : {"check", "dump", "format"}) {
            CAPTURE(deck);
            CAPTURE(command);
            const test::Run r = run_bounded(dir, std::string(command) + " " + deck);
            CHECK(r.exit_code == 2);
            CHECK(has(r.err, std::string(message) + ", not a deck file"));
        }
    }
}
}  // namespace test_special_files_cpp
