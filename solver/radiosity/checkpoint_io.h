#pragma once
// How a checkpoint writes and reads its values, numbers, strings, containers and the solver's records,
// byte for byte; private to checkpoint.cpp and checkpoint_identity.cpp, which lay out the file and its contents with them.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/backends/shot_stats.h"
#include "solver/formfactors/form_factor_row.h"
#include "solver/radiosity/ledger.h"
#include "solver/radiosity/progressive_solver.h"

// Writer, Reader and these transfer overloads share one namespace, so that lookup through Io finds
// them for any element type (Rgb is glm's); checkpoint.cpp's own types have theirs beside them.
namespace radmesh::checkpoint_io {

// FNV-1a 64: the payload's checksum and the meshed scene's hash.
inline std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash = 0xcbf29ce484222325ull) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 0x100000001b3ull;
  return hash;
}

// One field list per type serves writing and reading: transfer(io, x) with io a Writer or a Reader.
class Writer {
 public:
  std::string bytes;
  template <class T> void scalar(T& v) { bytes.append(reinterpret_cast<const char*>(&v), sizeof v); }
  void raw(char* data, std::size_t n) { bytes.append(data, n); }
  std::size_t count(std::size_t n);
  static constexpr bool reading = false;
};

struct Malformed {};  // the payload ends early or holds an impossible count (caught as corrupt)

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  template <class T> void scalar(T& v) { raw(reinterpret_cast<char*>(&v), sizeof v); }
  void raw(char* data, std::size_t n);
  std::size_t count(std::size_t);
  bool atEnd() const { return at_ == bytes_.size(); }
  std::string_view rest() const { return bytes_.substr(at_); }
  static constexpr bool reading = true;

 private:
  std::string_view bytes_;
  std::size_t at_ = 0;
};

template <class Io, class T>
  requires(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>)
void transfer(Io& io, T& v) {
  io.scalar(v);
}
template <class Io> void transfer(Io& io, bool& v) {
  std::uint8_t b = v ? 1 : 0;
  io.scalar(b);
  if (b > 1) throw Malformed{};
  v = b == 1;
}
template <class Io> void transfer(Io& io, std::string& s) {
  s.resize(io.count(s.size()));
  io.raw(s.data(), s.size());
}
template <class Io> void transfer(Io& io, Rgb& c);
template <class Io> void transfer(Io& io, Ledger& l);
template <class Io> void transfer(Io& io, nlohmann::json& j);
template <class Io> void transfer(Io& io, ShotStats& s);
template <class Io> void transfer(Io& io, IterationRecord& r);
template <class Io> void transfer(Io& io, FormFactorRow::BinShare& b);
template <class Io> void transfer(Io& io, FormFactorRow& r);
template <class Io, class A, class B> void transfer(Io& io, std::pair<A, B>& p);
template <class Io, class T> void transfer(Io& io, std::vector<T>& v);
template <class Io, class T> void transfer(Io& io, std::optional<T>& v);
template <class Io, class T> void transfer(Io& io, std::shared_ptr<const T>& v);

template <class Io, class... Field> void fields(Io& io, Field&... field) { (transfer(io, field), ...); }

template <class Io, class A, class B> void transfer(Io& io, std::pair<A, B>& p) { fields(io, p.first, p.second); }
template <class Io, class T> void transfer(Io& io, std::vector<T>& v) {
  v.resize(io.count(v.size()));
  for (T& x : v) transfer(io, x);
}
template <class Io, class T> void transfer(Io& io, std::optional<T>& v) {
  bool has = v.has_value();
  transfer(io, has);
  if (Io::reading) v = has ? std::optional<T>(T{}) : std::nullopt;
  if (has) transfer(io, *v);
}
template <class Io, class T> void transfer(Io& io, std::shared_ptr<const T>& v) {
  std::optional<T> value = v ? std::optional<T>(*v) : std::nullopt;
  transfer(io, value);
  if (Io::reading) v = value ? std::make_shared<const T>(std::move(*value)) : nullptr;
}
template <class Io> void transfer(Io& io, Rgb& c) { fields(io, c.r, c.g, c.b); }
template <class Io> void transfer(Io& io, Ledger& l) {
  for (double Ledger::*term : Ledger::kTerms) transfer(io, l.*term);
}
// JSON as its text: nlohmann writes the shortest decimal that reads back to the same double.
template <class Io> void transfer(Io& io, nlohmann::json& j) {
  std::string text = Io::reading ? std::string() : j.dump();
  transfer(io, text);
  if (Io::reading) {
    j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded()) throw Malformed{};
  }
}
template <class Io> void transfer(Io& io, ShotStats& s) { fields(io, s.machine, s.machineSeconds, s.figures); }
template <class Io> void transfer(Io& io, IterationRecord& r) {
  fields(io, r.iteration, r.shooters, r.shotPowerW, r.convergence, r.seconds, r.capturedFraction, r.reusedRows,
         r.reusedRowsTotal, r.cacheHits, r.ledger, r.elementsSplit, r.shotStats);
}
template <class Io> void transfer(Io& io, FormFactorRow::BinShare& b) { fields(io, b.patch, b.bin, b.formFactor); }
template <class Io> void transfer(Io& io, FormFactorRow& r) {
  fields(io, r.shooter, r.receivers, r.formFactors, r.backFaces, r.capturedFraction, r.reused, r.binShares,
         r.binBackFaces, r.binTotals);
}

template <class T> std::string bytesOf(T& value) {
  Writer writer;
  transfer(writer, value);
  return std::move(writer.bytes);
}

// Throws Malformed unless bytes hold exactly one T.
template <class T> T parsed(std::string_view bytes) {
  T value;
  Reader reader(bytes);
  transfer(reader, value);
  if (!reader.atEnd()) throw Malformed{};
  return value;
}

}  // namespace radmesh::checkpoint_io
