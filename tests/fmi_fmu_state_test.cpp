// FMU states through the C ABI: saved and restored (in memory and serialized, in the same and in
// another instance) they reproduce the following steps bit for bit; fmi3Reset restores every start
// value; bad FMU-state arguments and corrupted serialized states are refused.
#include <catch2/catch.hpp>
#include <cstdint>

#include "fmi_abi_support.hpp"

using Catch::Matchers::Contains;

namespace {

constexpr std::size_t kPoints = 11 * 11;

// ux, uy, errorL2 and time after each of the steps from t at loads 0.2, 0.4, ...
std::vector<std::vector<double>> continueRun(Session& s, double t, int steps) {
  std::vector<std::vector<double>> out;
  for (int k = 0; k < steps; ++k) {
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.2 * (k + 1)}) == fmi3OK);
    REQUIRE(s.step(t + 0.1 * k, 0.1) == fmi3OK);
    auto row = s.getFloat64(PERISTEP_VR_UX, kPoints);
    const auto uy = s.getFloat64(PERISTEP_VR_UY, kPoints);
    row.insert(row.end(), uy.begin(), uy.end());
    row.push_back(s.getFloat64(PERISTEP_VR_ERROR_L2).at(0));
    row.push_back(s.getFloat64(PERISTEP_VR_TIME).at(0));
    REQUIRE(row.size() == 2 * kPoints + 2);
    out.push_back(std::move(row));
  }
  return out;
}

// An 11 x 11 composite scene with non-default parameters, two steps into the run.
void prepare(Session& s) {
  REQUIRE(s.configure(11, 11, 2) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_COMPOSITE) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_XI, {0.3, -1.2}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.27}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_MODULUS_CONTRAST, {5.0}) == fmi3OK);
  REQUIRE(s.initialize(0, 10) == fmi3OK);
  continueRun(s, 0, 2);
}

std::vector<fmi3Byte> serialize(Session& s, fmi3FMUState state) {
  std::vector<fmi3Byte> bytes = s.serialize(state);
  REQUIRE(!bytes.empty());
  return bytes;
}

}  // namespace

TEST_CASE("a restored FMU state reproduces the following steps bit for bit", "[abi][fmustate]") {
  Session s;
  prepare(s);
  fmi3FMUState state = nullptr;
  REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &state) == fmi3OK);
  REQUIRE(state != nullptr);
  const auto reference = continueRun(s, 0.2, 3);

  SECTION("in memory, in the same instance") {
    REQUIRE(s.fmu.fmi3SetFMUState(s.instance, state) == fmi3OK);
    CHECK(continueRun(s, 0.2, 3) == reference);
    // and again: restoring does not consume the state
    REQUIRE(s.fmu.fmi3SetFMUState(s.instance, state) == fmi3OK);
    CHECK(continueRun(s, 0.2, 3) == reference);
  }

  SECTION("serialized, into another instance with other parameters in another state") {
    const auto bytes = serialize(s, state);
    Session other;  // the default structure (nx = ny = 33, nModes = 1): the state brings its own
    REQUIRE(other.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.1}) == fmi3OK);
    fmi3FMUState copy = nullptr;
    REQUIRE(other.fmu.fmi3DeserializeFMUState(other.instance, bytes.data(), bytes.size(), &copy) == fmi3OK);
    REQUIRE(other.fmu.fmi3SetFMUState(other.instance, copy) == fmi3OK);
    CHECK(other.getFloat64(PERISTEP_VR_POISSON_RATIO) == std::vector<double>{0.27});
    const fmi3ValueReference structural[] = {PERISTEP_VR_NX, PERISTEP_VR_NY, PERISTEP_VR_NMODES};
    fmi3UInt64 sizes[3] = {};
    REQUIRE(other.fmu.fmi3GetUInt64(other.instance, structural, 3, sizes, 3) == fmi3OK);
    CHECK(std::vector<fmi3UInt64>(sizes, sizes + 3) == std::vector<fmi3UInt64>{11, 11, 2});
    CHECK(continueRun(other, 0.2, 3) == reference);
    // serialization is deterministic
    CHECK(serialize(other, copy) == bytes);
    REQUIRE(other.fmu.fmi3FreeFMUState(other.instance, &copy) == fmi3OK);
    CHECK(copy == nullptr);
    CHECK(other.log.records.empty());
  }

  SECTION("saved into the memory of an earlier state") {
    fmi3FMUState reused = state;
    REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &reused) == fmi3OK);  // now at t = 0.5
    CHECK(reused == state);
    REQUIRE(s.fmu.fmi3SetFMUState(s.instance, state) == fmi3OK);
    CHECK(s.getFloat64(PERISTEP_VR_TIME) == std::vector<double>{0.5});
  }

  REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &state) == fmi3OK);
  CHECK(s.log.records.empty());
}

TEST_CASE("FMU-state arguments are checked", "[abi][fmustate]") {
  Session s;
  REQUIRE(s.configure(9, 9) == fmi3OK);
  fmi3FMUState state = nullptr;
  REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &state) == fmi3OK);
  const auto expectOneError = [&](const std::string& fragment) {
    REQUIRE(s.log.records.size() == 1);
    CHECK(s.log.records[0].status == fmi3Error);
    CHECK_THAT(s.log.records[0].message, Contains(fragment));
  };

  SECTION("a state of other structural parameters reconfigures the instance") {
    Session other;
    REQUIRE(other.configure(11, 9) == fmi3OK);
    const auto bytes = serialize(s, state);
    fmi3FMUState copy = nullptr;
    REQUIRE(other.fmu.fmi3DeserializeFMUState(other.instance, bytes.data(), bytes.size(), &copy) == fmi3OK);
    REQUIRE(other.fmu.fmi3SetFMUState(other.instance, copy) == fmi3OK);
    const fmi3ValueReference nx = PERISTEP_VR_NX;
    fmi3UInt64 value = 0;
    REQUIRE(other.fmu.fmi3GetUInt64(other.instance, &nx, 1, &value, 1) == fmi3OK);
    CHECK(value == 9);
    REQUIRE(other.initialize() == fmi3OK);
    CHECK(other.getFloat64(PERISTEP_VR_UX, 9 * 9).size() == 9 * 9);
    CHECK(other.log.records.empty());
    REQUIRE(other.fmu.fmi3FreeFMUState(other.instance, &copy) == fmi3OK);
  }
  SECTION("a state of another instance") {
    Session other;
    CHECK(other.fmu.fmi3SetFMUState(other.instance, state) == fmi3Error);
    REQUIRE(other.log.records.size() == 1);
    CHECK_THAT(other.log.records[0].message, Contains("FMUState was not created by this instance"));
  }
  SECTION("a freed state") {
    fmi3FMUState copy = state;
    REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &copy) == fmi3OK);
    CHECK(s.fmu.fmi3SetFMUState(s.instance, state) == fmi3Error);
    expectOneError("has been freed");
    state = nullptr;
  }
  SECTION("corrupt bytes") {
    auto bytes = serialize(s, state);
    bytes[bytes.size() / 2] ^= 0xFF;
    bytes.pop_back();
    fmi3FMUState copy = nullptr;
    CHECK(s.fmu.fmi3DeserializeFMUState(s.instance, bytes.data(), bytes.size(), &copy) == fmi3Error);
    expectOneError("serialized FMU state is corrupt");
  }
  SECTION("a changed or missing checksum") {
    auto bytes = serialize(s, state);
    bytes.back() ^= 0x01;
    fmi3FMUState copy = nullptr;
    CHECK(s.fmu.fmi3DeserializeFMUState(s.instance, bytes.data(), bytes.size(), &copy) == fmi3Error);
    expectOneError("checksum mismatch");
  }
  SECTION("bytes of something else") {
    const std::vector<fmi3Byte> junk(64, 7);
    fmi3FMUState copy = nullptr;
    CHECK(s.fmu.fmi3DeserializeFMUState(s.instance, junk.data(), junk.size(), &copy) == fmi3Error);
    expectOneError("does not start like a PeriStep FMU state");
  }
  SECTION("a buffer of the wrong size") {
    std::vector<fmi3Byte> bytes(8);
    CHECK(s.fmu.fmi3SerializeFMUState(s.instance, state, bytes.data(), bytes.size()) == fmi3Error);
    expectOneError("size = 8 but the serialized state has");
  }
  SECTION("NULL pointers") {
    CHECK(s.fmu.fmi3GetFMUState(s.instance, nullptr) == fmi3Error);
    expectOneError("fmi3GetFMUState: FMUState is NULL");
  }
  if (state) REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &state) == fmi3OK);
}

TEST_CASE("fmi3Reset restores every start value", "[abi][reset]") {
  Session s;
  REQUIRE(s.configure(9, 9, 2) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_COMPOSITE) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_LINEAR_SOLVER, PERISTEP_LINEAR_SOLVER_SPARSE_LU) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_XI, {1.0, -1.0}) == fmi3OK);
  for (fmi3ValueReference vr : {PERISTEP_VR_DELTA_OVER_H, PERISTEP_VR_MODULUS_CONTRAST})
    REQUIRE(s.setFloat64(vr, {4.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_JITTER, {0.1}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.45}) == fmi3OK);
  const fmi3ValueReference seed = PERISTEP_VR_SEED;
  const fmi3UInt64 seedValue = 42;
  REQUIRE(s.fmu.fmi3SetUInt64(s.instance, &seed, 1, &seedValue, 1) == fmi3OK);
  REQUIRE(s.initialize() == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.5}) == fmi3OK);
  REQUIRE(s.step(0, 0.25) == fmi3OK);

  REQUIRE(s.fmu.fmi3Reset(s.instance) == fmi3OK);
  const fmi3ValueReference u64[] = {PERISTEP_VR_NX, PERISTEP_VR_NY, PERISTEP_VR_NMODES, PERISTEP_VR_SEED};
  fmi3UInt64 u[4] = {};
  REQUIRE(s.fmu.fmi3GetUInt64(s.instance, u64, 4, u, 4) == fmi3OK);
  CHECK(std::vector<fmi3UInt64>(u, u + 4) == std::vector<fmi3UInt64>{33, 33, 1, 1});
  const fmi3ValueReference e[] = {PERISTEP_VR_SCENE, PERISTEP_VR_LINEAR_SOLVER};
  fmi3Int64 ev[2] = {};
  REQUIRE(s.fmu.fmi3GetInt64(s.instance, e, 2, ev, 2) == fmi3OK);
  CHECK(ev[0] == PERISTEP_SCENE_SMOOTH);
  CHECK(ev[1] == PERISTEP_LINEAR_SOLVER_UMFPACK);
  const fmi3ValueReference f[] = {PERISTEP_VR_LX, PERISTEP_VR_LY, PERISTEP_VR_DELTA_OVER_H,
                                  PERISTEP_VR_POISSON_RATIO, PERISTEP_VR_MODULUS_CONTRAST, PERISTEP_VR_JITTER,
                                  PERISTEP_VR_XI, PERISTEP_VR_LOAD_FACTOR};
  double fv[8] = {};
  REQUIRE(s.fmu.fmi3GetFloat64(s.instance, f, 8, fv, 8) == fmi3OK);
  CHECK(std::vector<double>(fv, fv + 8) == std::vector<double>{1, 1, 3, 0.3, 2, 0, 0, 1});
  // Instantiated again: the time has no value yet (asking is an error, which terminates) ...
  CHECK(s.getFloat64(PERISTEP_VR_TIME).empty());
  CHECK(s.log.errors() == 1);
  // ... and after another reset a new run works.
  REQUIRE(s.fmu.fmi3Reset(s.instance) == fmi3OK);
  s.log.clear();
  REQUIRE(s.configure(9, 9) == fmi3OK);
  REQUIRE(s.initialize() == fmi3OK);
  CHECK(s.step(0, 0.25) == fmi3OK);
  CHECK(s.log.records.empty());
}

TEST_CASE("every single-byte edit of a serialized state is refused", "[abi][fmustate]") {
  Session s;
  prepare(s);  // a state with a model checkpoint: parameters, solution and bond data
  fmi3FMUState state = nullptr;
  REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &state) == fmi3OK);
  const auto bytes = serialize(s, state);
  REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &state) == fmi3OK);
  std::size_t accepted = 0, tried = 0;
  for (std::size_t at = 0; at < bytes.size(); ++at)
    for (const fmi3Byte flip : {0x01, 0x80, 0xFF}) {
      auto edited = bytes;
      edited[at] ^= flip;
      fmi3FMUState copy = nullptr;
      ++tried;
      if (s.fmu.fmi3DeserializeFMUState(s.instance, edited.data(), edited.size(), &copy) == fmi3OK) {
        ++accepted;
        s.fmu.fmi3FreeFMUState(s.instance, &copy);
      }
    }
  INFO(tried << " edits of a state of " << bytes.size() << " bytes");
  CHECK(tried == 3 * bytes.size());
  CHECK(accepted == 0);
  CHECK(s.log.errors() == tried);  // one message per refusal
}
