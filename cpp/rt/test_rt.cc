// Tests of the real-time loop: the packet codec; the hot loop (RtLoop::run_cycles) makes no heap
// allocation, takes no pthread mutex and makes no system call besides clock_nanosleep, clock_gettime,
// recvfrom and sendto while a sender floods it with valid and malformed packets (counting operator
// new, an interposed pthread_mutex_lock and a seccomp filter that traps every other system call);
// packet validation, hold, timeout to zero; clean stop on divergence.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include <arpa/inet.h>
#include <dlfcn.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <pthread.h>
#include <signal.h>
#include <stddef.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <ucontext.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <thread>
#include <vector>

#include "packet.h"
#include "rt_loop.h"

// ---------------------------------------------------------------- counting hooks (this thread only)
namespace {
thread_local bool t_counting = false;
std::atomic<long> g_allocations{0};
std::atomic<long> g_mutex_locks{0};

void* counted_alloc(std::size_t size) {
  if (t_counting) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (size == 0) size = 1;
  if (void* p = std::malloc(size)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) { return counted_alloc(size); }
void* operator new[](std::size_t size) { return counted_alloc(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (t_counting) g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size ? size : 1);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  if (t_counting) g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size ? size : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

extern "C" int pthread_mutex_lock(pthread_mutex_t* m) {
  using Fn = int (*)(pthread_mutex_t*);
  static Fn real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "pthread_mutex_lock"));
  if (t_counting) g_mutex_locks.fetch_add(1, std::memory_order_relaxed);
  return real(m);
}

using namespace armrt::rt;

namespace {

int udp_socket() {
  const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a);
  timeval tv{0, 200000};
  ::setsockopt(s, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  return s;
}

sockaddr_in loopback(int port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  return a;
}

void send_raw(int s, int port, const std::uint8_t* b, int n) {
  const sockaddr_in to = loopback(port);
  ::sendto(s, b, n, 0, reinterpret_cast<const sockaddr*>(&to), sizeof to);
}

void send_exc(int s, int port, std::uint16_t type, std::uint32_t seq, const std::vector<double>& v) {
  std::uint8_t b[kMaxPacket];
  const int n = encode(b, type, seq, 0, v.data(), static_cast<int>(v.size()));
  send_raw(s, port, b, n);
}

// A sender that floods the loop with valid and malformed packets until stopped.
struct Flood {
  std::atomic<bool> stop{false};
  std::thread th;
  Flood(int port, int n_el) {
    th = std::thread([this, port, n_el] {
      const int s = udp_socket();
      std::vector<double> good(n_el, 0.02), nan(n_el, 0.1);
      nan[3] = std::numeric_limits<double>::quiet_NaN();
      std::uint8_t b[kMaxPacket];
      std::uint32_t seq = 1;
      unsigned rnd = 12345;
      while (!stop.load()) {
        send_exc(s, port, kExcitationElements, seq++, good);
        send_exc(s, port, kExcitationElements, seq - 1, good);       // duplicate
        send_exc(s, port, kExcitationElements, seq++, nan);          // NaN
        int n = encode(b, kExcitationElements, seq++, 0, good.data(), n_el);
        b[0] = 'X';
        send_raw(s, port, b, n);                                     // bad magic
        n = encode(b, kExcitationMuscles, seq++, 0, good.data(), 5);  // wrong count
        send_raw(s, port, b, n);
        for (int k = 0; k < 64; ++k) { rnd = rnd * 1103515245u + 12345u; b[k] = static_cast<std::uint8_t>(rnd >> 16); }
        send_raw(s, port, b, 1 + static_cast<int>(rnd % 64));        // garbage
        std::this_thread::sleep_for(std::chrono::microseconds(700));
      }
      ::close(s);
    });
  }
  ~Flood() {
    stop = true;
    th.join();
  }
};

RtConfig test_config() {
  RtConfig c;
  c.realtime = false;
  c.lock_memory = false;
  c.rate_hz = 1000;
  c.listen = "127.0.0.1:0";
  c.state_rate_hz = 500;
  c.send_forces = true;
  c.input_timeout = 0.05;
  c.channels = {"elbow_flexors", "rotator_cuff"};
  return c;
}

// ---------------------------------------------------------------- seccomp
std::atomic<int> g_trapped{0};
int g_trapped_nr[16];

void on_sigsys(int, siginfo_t* si, void* ctx) {
  const int k = g_trapped.fetch_add(1);
  if (k < 16) g_trapped_nr[k] = si->si_syscall;
  auto* uc = static_cast<ucontext_t*>(ctx);
  uc->uc_mcontext.gregs[REG_RAX] = -ENOSYS;
}

// Trapped system calls return -ENOSYS and are counted instead of killing the test.
void install_sigsys_handler() {
  struct sigaction sa {};
  sa.sa_sigaction = on_sigsys;
  sa.sa_flags = SA_SIGINFO;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGSYS, &sa, nullptr);
}

struct SeccompRun {
  RtLoop* loop;
  int n;
  bool installed = false;
};

void* seccomp_thread(void* arg) {
  auto* r = static_cast<SeccompRun*>(arg);
  const int allowed[] = {SYS_clock_nanosleep, SYS_clock_gettime, SYS_recvfrom, SYS_sendto, SYS_rt_sigreturn, SYS_exit};
  const int na = sizeof allowed / sizeof allowed[0];
  std::vector<sock_filter> f;
  f.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, arch)));
  f.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, AUDIT_ARCH_X86_64, 1, 0));
  f.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW));
  f.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr)));
  for (int k = 0; k < na; ++k)
    f.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, static_cast<unsigned>(allowed[k]), static_cast<unsigned char>(na - k), 0));
  f.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_TRAP));
  f.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW));
  sock_fprog prog{static_cast<unsigned short>(f.size()), f.data()};
  if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 || prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &prog) != 0)
    return nullptr;
  r->installed = true;  // from here on only the allowed system calls run
  if (r->loop) r->loop->run_cycles(r->n);
  else syscall(SYS_getppid);  // self-check: must be trapped
  syscall(SYS_exit, 0);  // the filter stays on this thread: leave without glibc's thread clean-up
  return nullptr;
}

}  // namespace

TEST_CASE("packet codec: round trip and header checks") {
  std::uint8_t b[kMaxPacket];
  const double v[3] = {0.1, 0.5, 1.0};
  const int n = encode(b, kExcitationGroups, 0xfffffffeu, kFlagForces, v, 3);
  CHECK(n == kHeaderSize + 24);
  CHECK(std::memcmp(b, "ARMR", 4) == 0);
  Header h;
  REQUIRE(decode_header(b, n, h) == DecodeError::kOk);
  CHECK(h.type == kExcitationGroups);
  CHECK(h.seq == 0xfffffffeu);
  CHECK(h.count == 3);
  CHECK(h.flags == kFlagForces);
  CHECK(get_f64(b + kHeaderSize + 8) == 0.5);
  CHECK(decode_header(b, n - 1, h) == DecodeError::kBadSize);
  CHECK(decode_header(b, 3, h) == DecodeError::kBadMagic);
  b[4] = 2;
  CHECK(decode_header(b, n, h) == DecodeError::kBadVersion);
  b[4] = 1;
  b[0] = 'a';
  CHECK(decode_header(b, n, h) == DecodeError::kBadMagic);
}

TEST_CASE("hot loop: no heap allocation and no mutex, under a packet flood") {
  RtLoop loop(test_config());
  loop.prepare_thread();
  Flood flood(loop.bound_port(), 102);
  loop.run_cycles(50);  // warm-up (first controller address, first packets)
  const long a0 = g_allocations.load(), m0 = g_mutex_locks.load();
  t_counting = true;
  loop.run_cycles(1500);
  t_counting = false;
  const long allocs = g_allocations.load() - a0, locks = g_mutex_locks.load() - m0;
  const RtStats st = loop.stats();
  CHECK(allocs == 0);
  CHECK(locks == 0);
  CHECK(st.cycles == 1550);
  CHECK(st.packets.applied > 100);
  CHECK(st.packets.non_finite > 100);
  CHECK(st.packets.bad_magic > 100);
  CHECK(st.packets.stale > 0);
  CHECK(st.packets.bad_count > 100);
  CHECK(st.packets.state_sent > 500);
  CHECK(loop.simulator().data.excitation[0] == doctest::Approx(0.02));
}

TEST_CASE("the counting hooks are in effect") {
  const long a0 = g_allocations.load(), m0 = g_mutex_locks.load();
  pthread_mutex_t m = PTHREAD_MUTEX_INITIALIZER;
  t_counting = true;
  int* p = new int(3);
  pthread_mutex_lock(&m);
  t_counting = false;
  pthread_mutex_unlock(&m);
  delete p;
  CHECK(g_allocations.load() - a0 == 1);
  CHECK(g_mutex_locks.load() - m0 == 1);
}

TEST_CASE("the seccomp trap is in effect") {
  install_sigsys_handler();
  const int before = g_trapped.load();
  SeccompRun run{nullptr, 0};
  pthread_t th;
  REQUIRE(pthread_create(&th, nullptr, seccomp_thread, &run) == 0);
  pthread_join(th, nullptr);
  if (!run.installed) {
    MESSAGE("seccomp filters are not available here (prctl PR_SET_SECCOMP failed): check skipped");
    return;
  }
  CHECK(g_trapped.load() - before == 1);
  CHECK(g_trapped_nr[before] == SYS_getppid);
  g_trapped.store(before);
}

TEST_CASE("hot loop: no system call besides clock_nanosleep, clock_gettime, recvfrom, sendto (seccomp)") {
  install_sigsys_handler();
  RtLoop loop(test_config());
  loop.prepare_thread();
  Flood flood(loop.bound_port(), 102);
  loop.run_cycles(50);
  SeccompRun run{&loop, 1000};
  pthread_t th;
  REQUIRE(pthread_create(&th, nullptr, seccomp_thread, &run) == 0);
  pthread_join(th, nullptr);
  if (!run.installed) {
    MESSAGE("seccomp filters are not available here (prctl PR_SET_SECCOMP failed): check skipped");
    return;
  }
  const int trapped = g_trapped.load();
  for (int k = 0; k < std::min(trapped, 16); ++k) MESSAGE("trapped system call " << g_trapped_nr[k]);
  CHECK(trapped == 0);
  const RtStats st = loop.stats();
  CHECK(st.cycles == 1050);
  CHECK(st.packets.applied > 50);
  CHECK(st.packets.state_sent > 300);
}

TEST_CASE("packets: mappings, sequence numbers, hold and timeout to zero") {
  RtConfig c = test_config();
  c.state_rate_hz = 0;
  RtLoop loop(c);
  const int port = loop.bound_port();
  const int s = udp_socket();
  auto& u = loop.simulator().data.excitation;
  const int n_el = loop.simulator().model.num_elements;
  const auto* def = loop.simulator().model.def;
  auto settle = [&] { usleep(3000); loop.run_cycles(2); };

  send_exc(s, port, kExcitationElements, 10, std::vector<double>(n_el, 0.3));
  settle();
  CHECK(u[0] == doctest::Approx(0.3));
  send_exc(s, port, kExcitationElements, 9, std::vector<double>(n_el, 0.9));  // out of order
  send_exc(s, port, kExcitationElements, 10, std::vector<double>(n_el, 0.9));  // duplicate
  std::vector<double> bad(n_el, 0.9);
  bad[7] = std::numeric_limits<double>::infinity();
  send_exc(s, port, kExcitationElements, 11, bad);
  send_exc(s, port, kExcitationElements, 12, std::vector<double>(n_el - 1, 0.9));  // wrong count
  send_exc(s, port, 99, 13, std::vector<double>(n_el, 0.9));                     // unknown type
  settle();
  CHECK(u[0] == doctest::Approx(0.3));  // held
  RtStats st = loop.stats();
  CHECK(st.packets.out_of_order == 1);
  CHECK(st.packets.stale == 1);
  CHECK(st.packets.non_finite == 1);
  CHECK(st.packets.bad_count == 1);
  CHECK(st.packets.bad_type == 1);

  // Channels: {elbow_flexors, rotator_cuff}; values outside [0, 1] are clipped.
  send_exc(s, port, kExcitationChannels, 20, {0.4, 1.7});
  settle();
  int ef = -1;
  for (int g = 0; g < def->num_groups; ++g) if (std::strcmp(def->groups[g].name, "elbow_flexors") == 0) ef = g;
  REQUIRE(ef >= 0);
  CHECK(u[def->groups[ef].elements[0]] == doctest::Approx(0.4));
  CHECK(loop.stats().packets.clipped == 1);
  // Muscles: one value per muscle.
  std::vector<double> mv(def->num_muscles, 0.0);
  mv[0] = 0.6;
  send_exc(s, port, kExcitationMuscles, 21, mv);
  settle();
  CHECK(u[def->muscles[0].elements[0]] == doctest::Approx(0.6));
  CHECK(u[def->muscles[1].elements[0]] == 0.0);

  // Silence longer than the timeout: the excitation falls to zero, then a restarted controller
  // (sequence from 0) is accepted.
  loop.run_cycles(80);
  CHECK(u[def->muscles[0].elements[0]] == 0.0);
  CHECK(loop.stats().packets.timeouts == 1);
  send_exc(s, port, kExcitationGroups, 0, std::vector<double>(def->num_groups, 0.05));
  settle();
  CHECK(u[def->groups[0].elements[0]] == doctest::Approx(0.05));
  ::close(s);
}

TEST_CASE("state packets reach the controller and describe the arm") {
  RtConfig c = test_config();
  c.state_rate_hz = 1000;
  RtLoop loop(c);
  const int s = udp_socket();
  send_exc(s, loop.bound_port(), kExcitationElements, 1, std::vector<double>(102, 0.0));
  loop.run_cycles(5);
  std::uint8_t b[kMaxPacket];
  const long n = ::recv(s, b, sizeof b, 0);
  Header h;
  REQUIRE(decode_header(b, n, h) == DecodeError::kOk);
  CHECK(h.type == kState);
  CHECK(h.count == kStateFixedValues + 102);
  CHECK((h.flags & kFlagForces) != 0);
  const double t = get_f64(b + kHeaderSize);
  CHECK(t > 0);
  CHECK(get_f64(b + kHeaderSize + 8 * 15) == 1.0);  // last applied seq
  ::close(s);
}

TEST_CASE("divergence stops the loop cleanly with the message") {
  RtConfig c = test_config();
  c.listen.clear();
  RtLoop loop(c);
  loop.simulator().model.max_joint_speed = 1e-9;  // any motion counts as divergence
  loop.simulator().data.excitation.fill(1.0);
  loop.run_cycles(1000);
  const RtStats st = loop.stats();
  CHECK(st.stop_reason == "diverged");
  CHECK(st.error.find("diverged") != std::string::npos);
  CHECK(st.cycles < 1000);
}

TEST_CASE("start / stop on a thread, with statistics") {
  RtConfig c = test_config();
  c.duration = 0.3;
  RtLoop loop(c);
  loop.start();
  loop.join();
  const RtStats st = loop.stats();
  CHECK(st.cycles == 300);
  CHECK(st.stop_reason == "duration");
  CHECK(st.latency.count == 300);
  CHECK(st.tet.median > 0);
  CHECK(st.tet.median < st.tet.max + 1);
  CHECK(loop.stats_json().find("\"overruns\"") != std::string::npos);
}
