#pragma once
// Run-time choice among samplers without virtual calls. A registry lists entries, each a
// struct with a name, a sampler template and the properties it sets (Registry::kOwn below):
//   struct NovakEntry { static constexpr std::string_view kName = "novak";
//                       template <typename Real> using Sampler = Novak<Real>; };
// A Choice is an index into the list; With(choice, query, f) builds the chosen sampler from
// the query (its fitting step) and calls f with it, so f is compiled once per sampler and
// the inner loop holds one branch on the index instead of an indirect call.
#include <array>
#include <optional>
#include <string>
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

// An entry's properties, each false unless the entry states it: Flag<Entry, Of>::value is
// Of<Entry>::value where the entry has the member Of reads, else false.
template <typename Entry, template <typename> class Of, typename = void>
struct Flag : std::false_type {};
template <typename Entry, template <typename> class Of>
struct Flag<Entry, Of, std::void_t<Of<Entry>>> : std::bool_constant<Of<Entry>::value> {};
template <typename E> using OwnOf = std::bool_constant<E::kOwn>;
template <typename E> using PolicyOf = std::bool_constant<E::kPolicy>;
template <typename E> using RoundTripInDistributionOf = std::bool_constant<E::kRoundTripInDistribution>;
template <typename E> using ThesisOf = std::bool_constant<E::kThesis>;
template <typename E> using BaselineOf = std::bool_constant<E::kBaseline>;

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
  // What the tools, charts and tests know of a sampler beyond its name:
  // kOwn: this project's sampler rather than a published one;
  // kPolicy: it chooses among the other samplers per query;
  // kRoundTripInDistribution: invert(sample(u)) == u holds in distribution only, not pointwise;
  // kThesis: proposed by Oppitz's thesis, whose claims the study tests on it;
  // kBaseline: the sampler every efficiency ratio is to (Novák's).
  static constexpr std::array<bool, kCount> kOwn = {detail::Flag<Entries, detail::OwnOf>::value...};
  static constexpr std::array<bool, kCount> kPolicy = {detail::Flag<Entries, detail::PolicyOf>::value...};
  static constexpr std::array<bool, kCount> kRoundTripInDistribution = {
      detail::Flag<Entries, detail::RoundTripInDistributionOf>::value...};
  static constexpr std::array<bool, kCount> kThesis = {detail::Flag<Entries, detail::ThesisOf>::value...};
  static constexpr std::array<bool, kCount> kBaseline = {detail::Flag<Entries, detail::BaselineOf>::value...};
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

  // The entry marked kBaseline (the first, should several be).
  static constexpr std::optional<Choice> Baseline() {
    for (std::size_t i = 0; i < kCount; ++i)
      if (kBaseline[i]) return Choice(static_cast<int>(i));
    return std::nullopt;
  }

  static constexpr std::optional<Choice> Parse(std::string_view name) {
    for (std::size_t i = 0; i < kCount; ++i)
      if (kNames[i] == name) return Choice(static_cast<int>(i));
    return std::nullopt;
  }

  // The table as JSON, one object per entry: name, label ("full-product" -> "FullProduct"),
  // own, policy, round_trip ("pointwise" or "distribution"), thesis, baseline. What the lab's scripts and charts
  // read (vrl_render --list-samplers, tools/samplers.py) instead of naming samplers themselves.
  static std::string ListJson() {
    std::string json = "[";
    for (std::size_t i = 0; i < kCount; ++i) {
      std::string label;
      bool word_start = true;
      for (char c : kNames[i]) {
        if (c == '-') {
          word_start = true;
          continue;
        }
        label += word_start && c >= 'a' && c <= 'z' ? char(c - 'a' + 'A') : c;
        word_start = false;
      }
      auto flag = [](bool b) { return b ? "true" : "false"; };
      json += std::string(i ? ",\n " : "\n ") + "{\"name\": \"" + std::string(kNames[i]) + "\", \"label\": \"" + label +
              "\", \"own\": " + flag(kOwn[i]) + ", \"policy\": " + flag(kPolicy[i]) + ", \"round_trip\": \"" +
              (kRoundTripInDistribution[i] ? "distribution" : "pointwise") + "\", \"thesis\": " + flag(kThesis[i]) +
              ", \"baseline\": " + flag(kBaseline[i]) + "}";
    }
    return json + "]";
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
