//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Many throws at once (batch_throws.hpp).  The reference is the serial loop
// of the single-throw calls the batch is built on: the batch must return the
// same bits in the same order, whatever the number of threads and the chunk
// size, and fail as the serial loop fails.
#include <gtest/gtest.h>

#include <spinslide/motion/batch_throws.hpp>
#include <spinslide/values/profile.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <deque>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace spinslide;

// Throws over every regime: ε = v0/ω0 log-uniform over [1e-3, 1e3] with ω0
// log-uniform over [1e-2, 1e2], and the exact cases (v0 = 0, ω0 = 0, both).
std::vector<throw_start<double>> starts(std::size_t n) {
  std::mt19937_64 rng(20260516);
  std::uniform_real_distribution<double> decade(-3, 3), spin_decade(-2, 2);
  std::vector<throw_start<double>> s;
  s.reserve(n + 3);
  for (std::size_t i = 0; i < n; ++i) {
    const double w0 = std::pow(10.0, spin_decade(rng));
    s.push_back({w0 * std::pow(10.0, decade(rng)), w0});
  }
  s.push_back({0, 2});
  s.push_back({3, 0});
  s.push_back({0, 0});
  return s;
}

// Bit for bit, NaN and infinities included.
bool same_bits(double a, double b) {
  std::uint64_t x = 0, y = 0;
  std::memcpy(&x, &a, sizeof a);
  std::memcpy(&y, &b, sizeof b);
  return x == y;
}

void expect_same(const stop_result<double>& batch, const stop_result<double>& serial,
                 std::size_t i) {
  EXPECT_TRUE(same_bits(batch.time, serial.time)) << i;
  EXPECT_TRUE(same_bits(batch.distance, serial.distance)) << i;
  EXPECT_TRUE(same_bits(batch.angle, serial.angle)) << i;
  EXPECT_EQ(batch.terminal.regime, serial.terminal.regime) << i;
  EXPECT_TRUE(same_bits(batch.terminal.ratio, serial.terminal.ratio)) << i;
}

const annulus<> cd(0.125);
const double gamma_cd = (1 + 0.125 * 0.125) / 2;

TEST(BatchThrows, EqualTheSerialCallsBitForBitOnOneTwoAndFourThreads) {
  const auto in = starts(300);
  std::vector<stop_result<double>> serial;
  serial.reserve(in.size());
  for (const auto& s : in) serial.push_back(simulate_throw(cd, gamma_cd, s.v0, s.omega0));
  for (const unsigned threads : {1U, 2U, 4U}) {
    for (const std::size_t chunk : {std::size_t(0), std::size_t(1), std::size_t(7)}) {
      batch_options o;
      o.threads = threads;
      o.chunk = chunk;
      const auto batch = stop_results(cd, gamma_cd, in, o);
      ASSERT_EQ(batch.size(), serial.size());
      for (std::size_t i = 0; i < in.size(); ++i) expect_same(batch[i], serial[i], i);
    }
  }
}

TEST(BatchThrows, AnyRandomAccessRangeOfStarts) {
  const std::array<throw_start<double>, 3> a = {{{1, 1}, {0.5, 2}, {2, 0.25}}};
  const std::deque<throw_start<double>> d(a.begin(), a.end());
  const uniform_disk<> disk;
  const auto from_array = stop_results(disk, 0.5, a);
  const auto from_deque = stop_results(disk, 0.5, d);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto serial = simulate_throw(disk, 0.5, a[i].v0, a[i].omega0);
    expect_same(from_array[i], serial, i);
    expect_same(from_deque[i], serial, i);
  }
}

TEST(BatchThrows, ThreadCountZeroIsTheHardwareDefault) {
  const unsigned hardware = std::thread::hardware_concurrency();
  const unsigned expected = hardware == 0 ? 1 : hardware;
  batch_options o;  // threads = 0
  EXPECT_EQ(detail::batch_threads(o, 1000000), expected);
  EXPECT_EQ(detail::batch_threads(o, 1), 1U);  // never more threads than throws
  o.threads = 3;
  EXPECT_EQ(detail::batch_threads(o, 1000000), 3U);
  // And the default gives the serial results.
  const auto in = starts(40);
  const auto batch = stop_results(cd, gamma_cd, in);
  for (std::size_t i = 0; i < in.size(); ++i)
    expect_same(batch[i], simulate_throw(cd, gamma_cd, in[i].v0, in[i].omega0), i);
}

TEST(BatchThrows, ProgressIsCalledFromTheCallerAndReachesTheTotal) {
  const auto in = starts(200);
  batch_options o;
  o.threads = 2;
  o.chunk = 1;
  o.progress_interval = std::chrono::milliseconds(1);
  std::vector<std::size_t> done;
  bool on_caller = true, total_right = true;
  const auto caller = std::this_thread::get_id();
  o.progress = [&](std::size_t d, std::size_t total) {
    on_caller = on_caller && std::this_thread::get_id() == caller;
    total_right = total_right && total == in.size();
    done.push_back(d);
  };
  stop_results(cd, gamma_cd, in, o);
  ASSERT_FALSE(done.empty());
  EXPECT_TRUE(on_caller);
  EXPECT_TRUE(total_right);
  EXPECT_EQ(done.back(), in.size());
  EXPECT_TRUE(std::is_sorted(done.begin(), done.end()));
}

// The serial loop's exception for the first bad throw.
template <class F>
std::string message_of(F f) {
  try {
    f();
  } catch (const std::domain_error& e) {
    return e.what();
  }
  return "no exception";
}

TEST(BatchThrows, ABadThrowInTheMiddleFailsAsTheSerialLoop) {
  auto in = starts(400);
  in[150].v0 = -1;                                            // the first bad throw
  in[151].omega0 = std::numeric_limits<double>::quiet_NaN();  // and one after it
  in[390].v0 = -2;
  const std::string serial = message_of([&] {
    for (const auto& s : in) simulate_throw(cd, gamma_cd, s.v0, s.omega0);
  });
  ASSERT_NE(serial.find("Got v0 = -1"), std::string::npos) << serial;
  for (const unsigned threads : {1U, 2U, 4U}) {
    for (const std::size_t chunk : {std::size_t(0), std::size_t(1), std::size_t(64)}) {
      batch_options o;
      o.threads = threads;
      o.chunk = chunk;
      EXPECT_EQ(message_of([&] { stop_results(cd, gamma_cd, in, o); }), serial)
          << threads << " threads, chunk " << chunk;
    }
  }
}

TEST(BatchThrows, AnErrnoPolicyGivesNaNAndTheOtherThrows) {
  using quiet = boost::math::policies::policy<
      boost::math::policies::domain_error<boost::math::policies::ignore_error>>;
  const annulus<double, quiet> q(0.125);
  auto in = starts(50);
  in[20].v0 = -1;
  batch_options o;
  o.threads = 2;
  const auto batch = stop_results(q, gamma_cd, in, o);
  for (std::size_t i = 0; i < in.size(); ++i)
    expect_same(batch[i], simulate_throw(q, gamma_cd, in[i].v0, in[i].omega0), i);
  EXPECT_TRUE(std::isnan(batch[20].time));
  EXPECT_FALSE(std::isnan(batch[21].time));
}

TEST(BatchThrows, AProgressThatThrowsStopsTheBatch) {
  const auto in = starts(400);
  batch_options o;
  o.threads = 2;
  o.chunk = 1;
  o.progress_interval = std::chrono::milliseconds(0);
  o.progress = [](std::size_t, std::size_t) { throw std::runtime_error("cancelled by the user"); };
  EXPECT_THROW(stop_results(cd, gamma_cd, in, o), std::runtime_error);
}

TEST(BatchThrows, AnEmptyBatch) {
  const std::vector<throw_start<double>> none;
  std::vector<std::size_t> calls;
  batch_options o;
  o.progress = [&](std::size_t d, std::size_t total) {
    calls.push_back(d);
    calls.push_back(total);
  };
  EXPECT_TRUE(stop_results(cd, gamma_cd, none, o).empty());
  EXPECT_EQ(calls, (std::vector<std::size_t>{0, 0}));
  const tabulated_throw<uniform_disk<>> table(uniform_disk<>(), 0.5);
  EXPECT_TRUE(stop_results(table, none).empty());
}

TEST(BatchThrows, TabulatedEqualsTheSerialCallsAndFailsAsThey) {
  const tabulated_throw<annulus<>> table(cd, gamma_cd);
  auto in = starts(5000);
  for (const unsigned threads : {1U, 2U, 4U}) {
    batch_options o;
    o.threads = threads;
    const auto batch = stop_results(table, in, o);
    ASSERT_EQ(batch.size(), in.size());
    for (std::size_t i = 0; i < in.size(); ++i) {
      EXPECT_TRUE(same_bits(batch[i].time, table.stop_time(in[i].v0, in[i].omega0))) << i;
      EXPECT_TRUE(same_bits(batch[i].distance, table.distance(in[i].v0, in[i].omega0))) << i;
    }
  }
  in[2500].omega0 = -3;
  in[4000].v0 = -4;
  const std::string serial = message_of([&] {
    for (const auto& s : in) table.stop_time(s.v0, s.omega0);
  });
  ASSERT_NE(serial.find("Got omega0 = -3"), std::string::npos) << serial;
  batch_options o;
  o.threads = 4;
  o.chunk = 3;
  EXPECT_EQ(message_of([&] { stop_results(table, in, o); }), serial);
}

// A user's pressure p(r) is called from every worker (batch_throws.hpp's
// thread-safety note): a pure function is safe, and the batch equals the
// serial loop.
TEST(BatchThrows, RadialProfileSharedByTheWorkers) {
  auto hertz_like = [](double r) { return std::sqrt(1 - r * r); };
  const radial_profile<double, decltype(hertz_like)> p(hertz_like);
  // A few throws: each evaluates p at thousands of quadrature nodes.
  const std::vector<throw_start<double>> in = {{0.1, 1}, {1, 1}, {2, 0.5}, {0.5, 3}};
  batch_options o;
  o.threads = 2;
  o.chunk = 1;
  const auto batch = stop_results(p, 0.4, in, o);
  for (std::size_t i = 0; i < in.size(); ++i)
    expect_same(batch[i], simulate_throw(p, 0.4, in[i].v0, in[i].omega0), i);
}

}  // namespace
