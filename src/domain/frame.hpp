// frame.hpp - the sampler's frame: the user's domain and radius, the
// internal coordinates every other layer works in, and the limits of both.
//
// Internally every coordinate is the user's multiplied by 2^k, chosen so the
// domain's largest |coordinate| lies in [1, 2). Scaling by a power of two is
// exact both ways, so every exact decision (distances, orientation) is the
// same in both frames, while products of coordinates can neither overflow nor
// underflow. Points are returned scaled back, bit for bit what was decided on.
//
// Limits (judged when the pair radius/domain is first used, see sampler.hpp):
//   - precision: R must be at least 2^-26 of the largest |coordinate|, so a
//     double still resolves the free regions; coordinates must not all lie
//     below 2^-900, and a nonzero one must not lie below 2^-900 times the
//     largest (scaling would underflow it: found by the fuzzer);
//   - periodic: R at most half the shorter period (a disk must not overlap
//     its own copies), and periods within kMaxPeriodRatio of each other;
//   - count: points index a 32-bit mesh (max_points()); count_bound() is a
//     rigorous bound on any pattern's size (Oler's inequality).
#ifndef PDS_FRAME_HPP
#define PDS_FRAME_HPP

#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <stdexcept>

#include "core/point.hpp"
#include "core/torus.hpp"
#include "domain/polygon.hpp"
#include "domain/rectangle.hpp"

namespace pds {

// Why a domain and radius cannot be sampled.
enum class Limit {
    ok,
    too_many_points,         // the points asked for exceed 32-bit indices or the address space
    radius_below_precision,  // R under 2^-26 of the coordinates' magnitude
    coordinates_too_small,   // |coordinates| all below 2^-900, or one nonzero below 2^-900 of the largest
    radius_exceeds_period,   // periodic domain: R above half the shorter period
    periods_too_unequal,     // periodic domain: the longer period above kMaxPeriodRatio times the shorter
    field_periods_too_unequal,  // a varying radius field on a torus longer than kMaxFieldPeriodRatio
};

// Which radius a limit was judged on: the one radius, a field's smallest or
// largest, or the lowest radius count mode can reach (so a message can name
// the one at fault).
// count_covered: count mode lowered it while fixed points' clearances,
// which shrink with it, still left no room for a point.
enum class JudgedRadius { radius, field_smallest, field_largest, count_lowest, count_covered };

// Thrown before anything changes when a call asks what the limits forbid.
class LimitError : public std::runtime_error {
public:
    LimitError(Limit limit, double user_radius, JudgedRadius judged = JudgedRadius::radius)
        : std::runtime_error("limit"), limit_(limit), radius_(user_radius), judged_(judged) {}
    Limit limit() const { return limit_; }
    double radius() const { return radius_; }  // the radius judged
    JudgedRadius judged() const { return judged_; }

private:
    Limit limit_;
    double radius_;
    JudgedRadius judged_;
};

class Frame {
public:
    // The torus is a plane triangulation with copies of the points out to the
    // largest empty circle (torus_copies.hpp). While a pattern is sparse that
    // circle spans the gaps along the longer period, so the copies along the
    // shorter one number about longer / shorter per point, nearly collinear:
    // a 10^4:1 torus took 6 s for a 10-point pds_free_area, 10^6:1 minutes.
    // Up to 1024:1 such a query stays under 0.05 s.
    static constexpr double kMaxPeriodRatio = 1024.0;
    // A varying radius field runs the Jones loop from the first point, so its
    // sparse start meets that cost on every thin torus (300 points of a
    // 1000:1 torus: seconds): such a torus is held to 16:1.
    static constexpr double kMaxFieldPeriodRatio = 16.0;
    // Whether a torus is longer than kMaxFieldPeriodRatio (user periods).
    bool periods_beyond(double ratio) const;

    // Requires x0 < x1, y0 < y1 finite and a finite radius > 0.
    Frame(const Box& user_domain, double user_radius);

    const Box& user_domain() const { return user_domain_; }
    double user_radius() const { return user_radius_; }
    // The internal frame: the domain's bounding box as a rectangle (the
    // domain itself without a polygon), its bounding box.
    const Rectangle& domain() const { return domain_; }
    // A polygonal domain (internal frame), or nullptr: the rectangle.
    const Polygon* polygon() const { return polygon_.get(); }
    const std::shared_ptr<const Polygon>& shared_polygon() const { return polygon_; }
    // Whether that polygon is the one set_polygon was given (read at the
    // internal scale), not a scaled copy beside it.
    bool shares_polygon() const { return polygon_ != nullptr && polygon_ == user_polygon_; }
    // The domain's area and perimeter (internal frame).
    double area() const { return polygon_ ? polygon_->area() : domain_.area(); }
    double perimeter() const { return polygon_ ? polygon_->perimeter() : domain_.perimeter(); }
    const Box& box() const { return domain_.bounds(); }
    double r() const { return r_; }

    void set_domain(const Box& user_domain);
    // A polygonal domain: user_polygon times 2^user_exp in user units
    // (nullptr: back to the rectangle user_domain()); its bounding box
    // becomes user_domain(). (A polygon whose coordinates would overflow or
    // underflow the predicates comes scaled: capi_domains.cpp.)
    void set_polygon(std::shared_ptr<const Polygon> user_polygon, int user_exp = 0);
    // The power of two e at which a polygon with these n coordinates (x, y,
    // ...) is best read (as coordinates / 2^e): the internal frame's, when
    // they all scale to it exactly, so that set_polygon takes the polygon as
    // built (one build, one copy in memory); else reading_exponent's, and
    // precision_limit() refuses such coordinates. Throws DomainError as
    // reading_exponent does.
    static int polygon_reading_exponent(const double* c, std::size_t n);
    void set_radius(double user_radius);
    void set_periodic(bool periodic);
    // Asked for, whether or not the domain allows it (precision_limit()).
    bool periodic() const { return torus_.has_value(); }
    // The periods and fundamental domain (internal frame); off when not periodic.
    const Torus& torus() const { return torus_ && torus_->on() ? *torus_ : kNoTorus; }

    Limit precision_limit() const;
    // Upper bound on the number of points of any pattern (Oler, 1961).
    double count_bound() const;
    // The expected size of a maximal pattern at user radius r: RSA's
    // saturation coverage pi R^2 N / (4A) = 0.547 plus, on a rectangle, the
    // edge excess 0.23 per R of perimeter (measured, README).
    double expected_count(double user_radius) const;
    // The largest user radius the domain allows (the torus: half the shorter
    // period; otherwise unbounded).
    double max_radius() const;
    // The user radius at which expected_count() is n.
    double radius_for_count(double n) const { return radius_for_count(n, area(), perimeter()); }
    // The same for a domain of that area and perimeter (internal frame):
    // what fixed points' clearances leave of this one (free_room.hpp).
    double radius_for_count(double n, double area, double perimeter) const;
    // A user radius below every radius count mode can reach on its way to n
    // points (sampler.cpp, lower_radius_for_count): it lowers R only when the
    // pattern is maximal at R with m < n points, and such a pattern's disks of
    // radius R cover the domain, so A <= m pi R^2 < n pi R^2; a step lowers R
    // by at most 1%. So R stays above 0.99 sqrt(A / (pi n)); 0.98 leaves room
    // for rounding.
    double lowest_count_radius(double n) const;
    // count_bound() as a count, saturated at max_points() + 1.
    std::size_t count_bound_points() const;
    // Largest number of points the index types and address space allow.
    static std::size_t max_points();

    Point to_user(const Point& p) const {
        // A product by a normal power of two rounds as ldexp does (once,
        // correctly) and costs no call: the copy of 10^7 points spent most
        // of its time in ldexp.
        if (to_user_factor_ != 0.0) return Point{p.x * to_user_factor_, p.y * to_user_factor_};
        return Point{std::ldexp(p.x, -scale_exp_), std::ldexp(p.y, -scale_exp_)};
    }
    Point to_internal(const Point& user) const;
    double area_to_user(double a) const;
    // A user radius in the internal frame, capped as r() is.
    double internal_radius(double user_radius) const;

private:
    Box user_domain_;
    double user_radius_;
    int scale_exp_ = 0;            // internal = user * 2^scale_exp_
    double to_user_factor_ = 1.0;  // 2^-scale_exp_ when a normal number, else 0
    std::shared_ptr<const Polygon> user_polygon_;  // as given (times 2^user_exp_), or nullptr
    int user_exp_ = 0;
    std::shared_ptr<const Polygon> polygon_;       // user_polygon_ scaled by 2^(scale_exp_ + user_exp_)
    double smallest_vertex_ = 0.0;                 // the polygon's smallest nonzero |coordinate|
    Rectangle domain_;   // on the torus, x1 and y1 are x0 + px and y0 + py rounded
    // Periodicity, stored once: none for a rectangle; periods on the torus
    // grid when asked for (off, px = 0, when the domain is too small for one).
    std::optional<Torus> torus_;
    static constexpr Torus kNoTorus{};
    double r_ = 0.0;     // internal radius (capped at twice the diagonal)
};

}  // namespace pds

#endif
