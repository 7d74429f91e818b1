// expansion.cpp - kernels of exact expansion arithmetic (see expansion.hpp).
//
// The algorithms follow Shewchuk (1997): linear-time merge-and-sum of two
// expansions, scaling by a double with error-free products, and compression.
// Invariant on every output: components in increasing magnitude, non-overlapping,
// no zero components.
#include "core/expansion.hpp"

#include <cmath>

namespace pds {

namespace {

// a + b where |a| >= |b| (or a == 0): sum + err exactly.
inline void fast_two_sum(double a, double b, double& sum, double& err) {
    sum = a + b;
    err = b - (sum - a);
}

}  // namespace

std::size_t expansion_sum(std::size_t elen, const double* e, std::size_t flen, const double* f,
                          double* h) {
    if (elen == 0) {
        for (std::size_t i = 0; i < flen; ++i) h[i] = f[i];
        return flen;
    }
    if (flen == 0) {
        for (std::size_t i = 0; i < elen; ++i) h[i] = e[i];
        return elen;
    }
    // Merge by magnitude, carrying a running sum q; emit the roundoff terms.
    std::size_t ei = 0, fi = 0, hn = 0;
    double enow = e[0], fnow = f[0];
    double q;
    if ((fnow > enow) == (fnow > -enow)) {
        q = enow;
        enow = (++ei < elen) ? e[ei] : 0.0;
    } else {
        q = fnow;
        fnow = (++fi < flen) ? f[fi] : 0.0;
    }
    double qnew, hh;
    if (ei < elen && fi < flen) {
        if ((fnow > enow) == (fnow > -enow)) {
            fast_two_sum(enow, q, qnew, hh);
            enow = (++ei < elen) ? e[ei] : 0.0;
        } else {
            fast_two_sum(fnow, q, qnew, hh);
            fnow = (++fi < flen) ? f[fi] : 0.0;
        }
        q = qnew;
        if (hh != 0.0) h[hn++] = hh;
        while (ei < elen && fi < flen) {
            if ((fnow > enow) == (fnow > -enow)) {
                two_sum(q, enow, qnew, hh);
                enow = (++ei < elen) ? e[ei] : 0.0;
            } else {
                two_sum(q, fnow, qnew, hh);
                fnow = (++fi < flen) ? f[fi] : 0.0;
            }
            q = qnew;
            if (hh != 0.0) h[hn++] = hh;
        }
    }
    while (ei < elen) {
        two_sum(q, enow, qnew, hh);
        enow = (++ei < elen) ? e[ei] : 0.0;
        q = qnew;
        if (hh != 0.0) h[hn++] = hh;
    }
    while (fi < flen) {
        two_sum(q, fnow, qnew, hh);
        fnow = (++fi < flen) ? f[fi] : 0.0;
        q = qnew;
        if (hh != 0.0) h[hn++] = hh;
    }
    if (q != 0.0 || hn == 0) h[hn++] = q;
    if (hn == 1 && h[0] == 0.0) return 0;
    return hn;
}

std::size_t expansion_scale(std::size_t elen, const double* e, double b, double* h) {
    if (elen == 0 || b == 0.0) return 0;
    std::size_t hn = 0;
    double q, hh, p1, p0, sum;
    two_product(e[0], b, q, hh);
    if (hh != 0.0) h[hn++] = hh;
    for (std::size_t i = 1; i < elen; ++i) {
        two_product(e[i], b, p1, p0);
        two_sum(q, p0, sum, hh);
        if (hh != 0.0) h[hn++] = hh;
        fast_two_sum(p1, sum, q, hh);
        if (hh != 0.0) h[hn++] = hh;
    }
    if (q != 0.0 || hn == 0) h[hn++] = q;
    if (hn == 1 && h[0] == 0.0) return 0;
    return hn;
}

std::size_t expansion_compress(std::size_t elen, double* e) {
    if (elen == 0) return 0;
    // Downward pass: absorb small components into larger ones.
    std::size_t bottom = elen - 1;
    double q = e[bottom];
    for (std::size_t i = elen - 1; i-- > 0;) {
        double qnew, small;
        fast_two_sum(q, e[i], qnew, small);
        if (small != 0.0) {
            e[bottom--] = qnew;
            q = small;
        } else {
            q = qnew;
        }
    }
    // Upward pass: re-emit in increasing order.
    std::size_t top = 0;
    for (std::size_t i = bottom + 1; i < elen; ++i) {
        double qnew, small;
        fast_two_sum(e[i], q, qnew, small);
        if (small != 0.0) e[top++] = small;
        q = qnew;
    }
    if (q != 0.0) e[top++] = q;
    return top;
}

// ---- heap expansions -------------------------------------------------------------

Expansion operator+(const Expansion& x, const Expansion& y) {
    Expansion r;
    r.c_.resize(x.c_.size() + y.c_.size());
    const std::size_t n =
        expansion_sum(x.c_.size(), x.c_.data(), y.c_.size(), y.c_.data(), r.c_.data());
    r.c_.resize(n);
    return r;
}

Expansion Expansion::operator-() const {
    Expansion r = *this;
    for (double& v : r.c_) v = -v;
    return r;
}

Expansion operator-(const Expansion& x, const Expansion& y) { return x + (-y); }

Expansion Expansion::scaled(double b) const {
    Expansion r;
    r.c_.resize(2 * c_.size());
    r.c_.resize(expansion_scale(c_.size(), c_.data(), b, r.c_.data()));
    return r;
}

Expansion operator*(const Expansion& x, const Expansion& y) {
    const Expansion& big = x.c_.size() >= y.c_.size() ? x : y;
    const Expansion& small = x.c_.size() >= y.c_.size() ? y : x;
    Expansion acc;
    for (double b : small.c_) acc = acc + big.scaled(b);
    acc.c_.resize(expansion_compress(acc.c_.size(), acc.c_.data()));
    return acc;
}

Rational make_rational(const Expansion& num, const Expansion& den) {
    if (den.sign() < 0) return Rational{-num, -den};
    return Rational{num, den};
}

int compare(const Rational& a, const Rational& b) {
    return (a.num * b.den - b.num * a.den).sign();
}

}  // namespace pds
