#include "fmi/fmu_state.hpp"

#include <cstring>
#include <string>

#include "core/checksum.hpp"

#include "fmi/model_identity.hpp"

namespace peristep::fmi {

namespace {

constexpr std::uint32_t kMagic = 0x53505350;  // "PSPS"
constexpr std::uint32_t kFormat = 4;  // 4: the dynamic state holds its force-evaluation count

bool knownState(std::uint32_t s) {
  return s == Instantiated || s == ConfigurationMode || s == InitializationMode || s == StepMode || s == Terminated;
}

}  // namespace

std::vector<std::uint8_t> serialize(const Snapshot& s) {
  ByteWriter out;
  out.put(kMagic);
  out.put(kFormat);
  // The instantiation token identifies the variable table the state was written against.
  out.putArray(std::span<const char>(kInstantiationToken.data(), kInstantiationToken.size()));
  out.put<std::uint32_t>(s.state);
  out.put(s.time);
  out.put<std::uint8_t>(s.stopTimeDefined);
  out.put(s.stopTime);
  s.values.write(out);
  out.put<std::uint8_t>(s.solutionValid);
  out.put<std::uint8_t>(s.setSinceStep);
  out.put<std::uint8_t>(s.hasModel);
  out.putArray(std::span<const std::uint8_t>(s.model));
  std::vector<std::uint8_t> bytes = out.take();
  const std::uint64_t sum = fnv1a64(bytes);
  const auto* p = reinterpret_cast<const std::uint8_t*>(&sum);
  bytes.insert(bytes.end(), p, p + sizeof sum);
  return bytes;
}

Snapshot deserialize(std::span<const std::uint8_t> bytes) {
  ByteReader head(bytes);
  if (head.get<std::uint32_t>() != kMagic) ByteReader::corrupt("it does not start like a PeriStep FMU state");
  if (const auto f = head.get<std::uint32_t>(); f != kFormat)
    ByteReader::corrupt("format " + std::to_string(f) + ", this build reads format " + std::to_string(kFormat));
  // The checksum before anything else is read: a value edited into another legal value would pass
  // every check below.
  std::uint64_t stored = 0;
  if (bytes.size() < 2 * sizeof(std::uint32_t) + sizeof stored) ByteReader::corrupt("it ends early");
  const auto payload = bytes.first(bytes.size() - sizeof stored);
  std::memcpy(&stored, bytes.data() + payload.size(), sizeof stored);
  if (fnv1a64(payload) != stored) ByteReader::corrupt("checksum mismatch (the bytes were changed or truncated)");
  ByteReader in(payload);
  in.get<std::uint32_t>();  // magic and format, checked above
  in.get<std::uint32_t>();
  const auto token = in.getArray<char>();
  if (std::string_view(token.data(), token.size()) != kInstantiationToken)
    ByteReader::corrupt("it was written by another PeriStep build (instantiation token differs)");
  Snapshot s;
  const auto state = in.get<std::uint32_t>();
  if (!knownState(state)) ByteReader::corrupt("unknown FMI state " + std::to_string(state));
  s.state = static_cast<State>(state);
  s.time = in.get<double>();
  s.stopTimeDefined = in.get<std::uint8_t>() != 0;
  s.stopTime = in.get<double>();
  s.values = ParameterValues::read(in);
  s.solutionValid = in.get<std::uint8_t>() != 0;
  s.setSinceStep = in.get<std::uint8_t>() != 0;
  s.hasModel = in.get<std::uint8_t>() != 0;
  s.model = in.getArray<std::uint8_t>();
  if (in.remaining() != 0) ByteReader::corrupt(std::to_string(in.remaining()) + " bytes follow the state");
  return s;
}

}  // namespace peristep::fmi
