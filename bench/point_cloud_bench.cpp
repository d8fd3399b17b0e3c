// Point-cloud transform throughput on one core: doTransform on Eigen::Matrix3Xd and on
// std::vector<Eigen::Vector3d>, next to the naive per-point loop (quaternion applied point by
// point) that the cloud overloads replace.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "lcmtf/do_transform.hpp"

namespace {

constexpr long kPoints = 1'000'000;

const lcmtf::Transform& sensorInMap() {
  static const lcmtf::Transform map_T_sensor(
      Eigen::Vector3d(1.5, -0.25, 0.8),
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, -0.4, 1.0).normalized())));
  return map_T_sensor;
}

const std::vector<Eigen::Vector3d>& pointList() {
  static const std::vector<Eigen::Vector3d> points = [] {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-30.0, 30.0);
    std::vector<Eigen::Vector3d> cloud(kPoints);
    for (Eigen::Vector3d& p : cloud)
      p = {coordinate(random), coordinate(random), coordinate(random)};
    return cloud;
  }();
  return points;
}

const Eigen::Matrix3Xd& pointMatrix() {
  static const Eigen::Matrix3Xd matrix = [] {
    Eigen::Matrix3Xd cloud(3, kPoints);
    for (long i = 0; i < kPoints; ++i) cloud.col(i) = pointList()[static_cast<std::size_t>(i)];
    return cloud;
  }();
  return matrix;
}

void setThroughput(benchmark::State& state) {
  state.SetItemsProcessed(state.iterations() * kPoints);
  state.counters["Mpoints/s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * kPoints) * 1e-6, benchmark::Counter::kIsRate);
}

void matrixCloud(benchmark::State& state) {
  const Eigen::Matrix3Xd& cloud = pointMatrix();
  for (auto _ : state) {
    Eigen::Matrix3Xd moved = lcmtf::transformed(sensorInMap(), cloud);
    benchmark::DoNotOptimize(moved.data());
  }
  setThroughput(state);
}

void vectorCloud(benchmark::State& state) {
  const std::vector<Eigen::Vector3d>& cloud = pointList();
  for (auto _ : state) {
    std::vector<Eigen::Vector3d> moved = lcmtf::transformed(sensorInMap(), cloud);
    benchmark::DoNotOptimize(moved.data());
  }
  setThroughput(state);
}

void naivePerPoint(benchmark::State& state) {
  const std::vector<Eigen::Vector3d>& cloud = pointList();
  const lcmtf::Transform& map_T_sensor = sensorInMap();
  for (auto _ : state) {
    std::vector<Eigen::Vector3d> moved;
    moved.reserve(cloud.size());
    for (const Eigen::Vector3d& p : cloud)
      moved.push_back(map_T_sensor.rotation * p + map_T_sensor.translation);
    benchmark::DoNotOptimize(moved.data());
  }
  setThroughput(state);
}

}  // namespace

BENCHMARK(matrixCloud)->Name("cloud_1M/Matrix3Xd")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(vectorCloud)
    ->Name("cloud_1M/vector<Vector3d>")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(naivePerPoint)
    ->Name("cloud_1M/naive_per_point_quaternion")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_MAIN();
