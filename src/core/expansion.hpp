// expansion.hpp - exact arithmetic on floating-point expansions.
//
// An expansion is an unevaluated sum of doubles, kept in increasing order of
// magnitude, non-overlapping and with zeros eliminated, so its sign is the sign
// of its last (largest) component (Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997).
// Every operation here is exact as long as nothing overflows or underflows;
// the sampler keeps its coordinates scaled into [-2, 2] so that holds.
//
// Two flavours share the same kernels:
//   FixedExpansion<N>  capacity fixed at compile time, never allocates: used by
//                      the predicates, which run while the mesh is being changed.
//   Expansion          heap storage of any length: used by the rare exact cell
//                      classification and by verification, never mid-mutation.
//
// Requires IEEE-754 double arithmetic with round-to-nearest-even and no
// contraction of a*b+c into fused operations (the build uses -ffp-contract=off).
#ifndef PDS_EXPANSION_HPP
#define PDS_EXPANSION_HPP

#include <cmath>
#include <cstddef>
#include <vector>

namespace pds {

// ---- error-free transformations ------------------------------------------------

// a + b == sum + err exactly.
inline void two_sum(double a, double b, double& sum, double& err) {
    sum = a + b;
    const double bv = sum - a;
    const double av = sum - bv;
    err = (a - av) + (b - bv);
}

// a - b == diff + err exactly.
inline void two_diff(double a, double b, double& diff, double& err) {
    diff = a - b;
    const double bv = a - diff;
    const double av = diff + bv;
    err = (a - av) + (bv - b);
}

// a * b == prod + err exactly (the fused multiply-add is exact by definition).
inline void two_product(double a, double b, double& prod, double& err) {
    prod = a * b;
    err = std::fma(a, b, -prod);
}

// ---- kernels on raw component arrays; each returns the output length ------------

// h = e + f. h must hold elen + flen components and may not alias e or f.
std::size_t expansion_sum(std::size_t elen, const double* e, std::size_t flen, const double* f,
                          double* h);
// h = e * b. h must hold 2 * elen components and may not alias e.
std::size_t expansion_scale(std::size_t elen, const double* e, double b, double* h);
// e = the same value in fewer components; in place.
std::size_t expansion_compress(std::size_t elen, double* e);
// Sign of an expansion kept by the kernels above: -1, 0 or +1.
inline int expansion_sign(std::size_t elen, const double* e) {
    if (elen == 0) return 0;
    return e[elen - 1] > 0.0 ? 1 : (e[elen - 1] < 0.0 ? -1 : 0);
}

// ---- fixed capacity ----------------------------------------------------------------

template <std::size_t N>
struct FixedExpansion {
    std::size_t n = 0;
    double c[N];

    FixedExpansion() = default;
    int sign() const { return expansion_sign(n, c); }
};

inline FixedExpansion<2> exact_value(double a) {
    FixedExpansion<2> r;
    if (a != 0.0) r.c[r.n++] = a;
    return r;
}

inline FixedExpansion<2> exact_diff(double a, double b) {
    FixedExpansion<2> r;
    double d, e;
    two_diff(a, b, d, e);
    if (e != 0.0) r.c[r.n++] = e;
    if (d != 0.0) r.c[r.n++] = d;
    return r;
}

inline FixedExpansion<2> exact_product(double a, double b) {
    FixedExpansion<2> r;
    double p, e;
    two_product(a, b, p, e);
    if (e != 0.0) r.c[r.n++] = e;
    if (p != 0.0) r.c[r.n++] = p;
    return r;
}

template <std::size_t A, std::size_t B>
FixedExpansion<A + B> operator+(const FixedExpansion<A>& x, const FixedExpansion<B>& y) {
    FixedExpansion<A + B> r;
    r.n = expansion_sum(x.n, x.c, y.n, y.c, r.c);
    return r;
}

template <std::size_t A>
FixedExpansion<A> operator-(const FixedExpansion<A>& x) {
    FixedExpansion<A> r = x;
    for (std::size_t i = 0; i < r.n; ++i) r.c[i] = -r.c[i];
    return r;
}

template <std::size_t A, std::size_t B>
FixedExpansion<A + B> operator-(const FixedExpansion<A>& x, const FixedExpansion<B>& y) {
    return x + (-y);
}

// Product: the sum over y's components of x scaled by each; compressed at the end
// so that later operations stay short.
template <std::size_t A, std::size_t B>
FixedExpansion<2 * A * B> operator*(const FixedExpansion<A>& x, const FixedExpansion<B>& y) {
    FixedExpansion<2 * A * B> acc, tmp;
    double scaled[2 * A];
    for (std::size_t i = 0; i < y.n; ++i) {
        const std::size_t m = expansion_scale(x.n, x.c, y.c[i], scaled);
        tmp.n = expansion_sum(acc.n, acc.c, m, scaled, tmp.c);
        acc.n = tmp.n;
        for (std::size_t k = 0; k < tmp.n; ++k) acc.c[k] = tmp.c[k];
    }
    acc.n = expansion_compress(acc.n, acc.c);
    return acc;
}

// ---- heap storage --------------------------------------------------------------------

class Expansion {
public:
    Expansion() = default;
    explicit Expansion(double a) {
        if (a != 0.0) c_.push_back(a);
    }
    template <std::size_t N>
    explicit Expansion(const FixedExpansion<N>& f) : c_(f.c, f.c + f.n) {}

    static Expansion diff(double a, double b) { return Expansion(exact_diff(a, b)); }
    static Expansion product(double a, double b) { return Expansion(exact_product(a, b)); }

    friend Expansion operator+(const Expansion& x, const Expansion& y);
    friend Expansion operator-(const Expansion& x, const Expansion& y);
    friend Expansion operator*(const Expansion& x, const Expansion& y);
    Expansion operator-() const;
    Expansion scaled(double b) const;

    int sign() const { return expansion_sign(c_.size(), c_.data()); }
    std::size_t size() const { return c_.size(); }
    // Its value to about double precision (the components summed).
    double estimate() const {
        double sum = 0.0;
        for (double c : c_) sum += c;
        return sum;
    }

private:
    std::vector<double> c_;
};

// Exact rational number num/den with den > 0, for comparisons only.
struct Rational {
    Expansion num;
    Expansion den;
};
// Builds num/den with any nonzero den (the sign is moved into the numerator).
Rational make_rational(const Expansion& num, const Expansion& den);
// Sign of a - b.
int compare(const Rational& a, const Rational& b);

}  // namespace pds

#endif
