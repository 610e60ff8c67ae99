#pragma once
// Run-time choice among samplers without virtual calls. A registry lists entries, each a
// struct with a name, a sampler template and, where it holds, kRoundTripInDistribution:
//   struct NovakEntry { static constexpr std::string_view kName = "novak";
//                       template <typename Real> using Sampler = Novak<Real>; };
// A Choice is an index into the list; With(choice, query, f) builds the chosen sampler from
// the query (its fitting step) and calls f with it, so f is compiled once per sampler and
// the inner loop holds one branch on the index instead of an indirect call.
#include <array>
#include <optional>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "query.hpp"

namespace vrlis {

// A type passed as a value (to a generic lambda, which reads it back as decltype(arg)::type).
template <typename T>
struct Type {
  using type = T;
};

template <typename Registry>
class Choice {
 public:
  constexpr Choice() = default;
  constexpr int index() const { return index_; }
  constexpr std::string_view name() const { return Registry::kNames[static_cast<std::size_t>(index_)]; }
  friend constexpr bool operator==(Choice a, Choice b) { return a.index_ == b.index_; }
  friend constexpr bool operator!=(Choice a, Choice b) { return a.index_ != b.index_; }

 private:
  friend Registry;
  constexpr explicit Choice(int index) : index_(index) {}
  int index_ = 0;
};

namespace detail {
template <typename Query>
struct RealOf;
template <template <typename> class Query, typename R>
struct RealOf<Query<R>> {
  using type = R;
};

// Entry::kRoundTripInDistribution where the entry states it, else false.
template <typename Entry, typename = void>
struct RoundTripInDistribution : std::false_type {};
template <typename Entry>
struct RoundTripInDistribution<Entry, std::void_t<decltype(Entry::kRoundTripInDistribution)>>
    : std::bool_constant<Entry::kRoundTripInDistribution> {};

template <typename F, typename Entry, typename... Rest>
decltype(auto) DispatchEntry(int index, F& f) {
  if constexpr (sizeof...(Rest) == 0) {
    return f(Entry{});
  } else {
    if (index == 0) return f(Entry{});
    return DispatchEntry<F, Rest...>(index - 1, f);
  }
}
}  // namespace detail

template <typename... Entries>
struct Registry {
  using Choice = vrlis::Choice<Registry>;
  static constexpr std::size_t kCount = sizeof...(Entries);
  static constexpr std::array<std::string_view, kCount> kNames = {Entries::kName...};
  // Per entry: invert(sample(u)) == u holds in distribution only, not pointwise (so a check
  // of the round trip compares distributions for it).
  static constexpr std::array<bool, kCount> kRoundTripInDistribution = {
      detail::RoundTripInDistribution<Entries>::value...};
  // Every sampler in precision Real, as a type list (e.g. for a test over all of them).
  template <typename Real>
  using Samplers = std::tuple<typename Entries::template Sampler<Real>...>;

  template <typename Entry>
  static constexpr Choice Of() {
    int index = 0, found = -1;
    ((found = std::is_same_v<Entry, Entries> ? index : found, ++index), ...);
    return Choice(found);
  }

  static constexpr std::array<Choice, kCount> All() {
    std::array<Choice, kCount> all{};
    for (std::size_t i = 0; i < kCount; ++i) all[i] = Choice(static_cast<int>(i));
    return all;
  }

  static constexpr std::optional<Choice> Parse(std::string_view name) {
    for (std::size_t i = 0; i < kCount; ++i)
      if (kNames[i] == name) return Choice(static_cast<int>(i));
    return std::nullopt;
  }

  // Returns f(Entry{}) for the chosen entry: a caller that builds many samplers of one
  // choice branches once, outside its loop, and its loop is compiled per sampler.
  template <typename F>
  static decltype(auto) WithEntry(Choice c, F&& f) {
    return detail::DispatchEntry<F, Entries...>(c.index(), f);
  }

  // Builds the chosen sampler from q and returns f(sampler); f must return one type for all.
  template <typename Query, typename F>
  static decltype(auto) With(Choice c, const Query& q, F&& f) {
    return WithEntry(c, [&](auto entry) {
      return f(typename decltype(entry)::template Sampler<typename detail::RealOf<Query>::type>(q));
    });
  }
  // The same for a query the caller has validated (no second validation).
  template <typename Query, typename F>
  static decltype(auto) With(Choice c, ValidQuery, const Query& q, F&& f) {
    return WithEntry(c, [&](auto entry) {
      return f(typename decltype(entry)::template Sampler<typename detail::RealOf<Query>::type>(ValidQuery{}, q));
    });
  }
};

}  // namespace vrlis
