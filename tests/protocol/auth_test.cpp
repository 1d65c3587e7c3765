// Message signatures: a signed message verifies on its channel under the same secret, and any
// change (a byte, the channel, the secret, no signature at all) fails; secret files are checked.
#include "auth.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "channels.h"
#include "olympics/action_batch_t.hpp"
#include "process.h"
#include "transport.h"

namespace olympics::protocol {
namespace {

std::vector<std::uint8_t> action_bytes() {
  olympics::action_batch_t a;
  a.match_id = "srv-k1-3", a.client_id = "alice-1", a.tick = 12, a.num_slots = 1, a.slots = {0};
  a.action_size = 3, a.actions = {{0.1f, 0.2f, 0.3f}};
  return encode(a);
}

TEST(Auth, ASignedMessageVerifiesAndAnyChangeFails) {
  const Authenticator auth("a lab's deployment secret");
  const std::string channel = action_channel("srv-k1-3");
  auto bytes = action_bytes();
  const int n = static_cast<int>(bytes.size());
  EXPECT_FALSE(auth.verify(channel, bytes.data(), n)) << "unsigned (zeros)";
  auth.sign(channel, bytes.data(), n);
  EXPECT_TRUE(auth.verify(channel, bytes.data(), n));
  EXPECT_TRUE(decode<olympics::action_batch_t>(bytes.data(), n)) << "still the same message";
  EXPECT_FALSE(auth.verify(action_channel("srv-k1-4"), bytes.data(), n)) << "another channel";
  EXPECT_FALSE(Authenticator("another deployment's secret").verify(channel, bytes.data(), n));
  for (int i = 0; i < n; i += 7) {
    auto changed = bytes;
    changed[i] ^= 1;
    EXPECT_FALSE(auth.verify(channel, changed.data(), n)) << "byte " << i;
  }
  EXPECT_FALSE(auth.verify(channel, bytes.data(), 20)) << "too short to be ours";
}

TEST(Auth, SendersAreTheServersOrTheClientsByChannel) {
  EXPECT_EQ(sender_of(kAnnounce), Role::Server);
  EXPECT_EQ(sender_of(kResult), Role::Server);
  EXPECT_EQ(sender_of(obs_channel("m")), Role::Server);
  EXPECT_EQ(sender_of(action_channel("m")), Role::Client);
  EXPECT_EQ(sender_of(obs_bundle_channel("c")), Role::Server);
  EXPECT_EQ(sender_of(action_bundle_channel("s")), Role::Client);
  EXPECT_EQ(sender_of(kJoin), Role::Client);
  EXPECT_EQ(sender_of(kLeague), Role::Client);
}

TEST(Auth, SecretFilesAreMadePrivateAndCheckedWhenRead) {
  const std::string dir = temp_dir(), path = dir + "/secret";
  write_new_secret(path);
  struct stat st {};
  ASSERT_EQ(stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_NO_THROW(Authenticator::from_file(path));
  EXPECT_THROW(write_new_secret(path), std::runtime_error) << "never overwrites a secret";
  chmod(path.c_str(), 0644);
  try {
    Authenticator::from_file(path);
    ADD_FAILURE() << "a secret others can read was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("chmod 600"), std::string::npos) << e.what();
  }
  const std::string short_path = dir + "/short";
  std::ofstream(short_path) << "hunter2\n";
  chmod(short_path.c_str(), 0600);
  EXPECT_THROW(Authenticator::from_file(short_path), std::runtime_error);
  try {
    Authenticator::from_file(dir + "/missing");
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("olympics-server secret"), std::string::npos) << e.what();
  }
}

// A FIFO (or a device, a folder) given as the secret: reading it blocked forever, so even
// `olympics-server serve --dry-run` hung in silence (issue 36, item 9).
TEST(Auth, ASecretThatIsNotARegularFileIsRefusedWithoutReadingIt) {
  const std::string dir = temp_dir(), fifo = dir + "/fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path : {fifo, dir}) {
    chmod(path.c_str(), 0700);
    try {
      Authenticator::from_file(path);
      ADD_FAILURE() << path << " was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("is not a regular file"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace olympics::protocol
