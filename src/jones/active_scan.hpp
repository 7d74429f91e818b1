// active_scan.hpp - the free regions' active list scanned in steps: the
// sites whose bound is still positive kept in order, their bounds summed in
// that order.
//
// Why in steps. Each epoch of the free regions' darts starts by scanning
// the active list (jones_loop_regions.cpp): drop the covered sites, sum the
// others' bounds, which sets the epoch's length. In the plane the bounds of
// the sites already listed do not change while the last epoch's points are
// inserted (only the new cells are measured, plane_space.hpp), so that scan
// can run beside those insertions, on the helper thread, a step at a time
// between its walks (ring_prefetcher.hpp); the epoch then only adds the new
// sites. The sum is the same left-to-right sum of the same doubles, so the
// points do not depend on who scanned.
//
// In place. The kept sites move down within the list; the list keeps its
// size until take() or seal(), which only the caller calls, after the
// helper is joined. A dropped site had bound 0: covered for good.
#ifndef PDS_ACTIVE_SCAN_HPP
#define PDS_ACTIVE_SCAN_HPP

#include <cstddef>
#include <vector>

#include "core/indices.hpp"
#include "jones/free_area_tree.hpp"

namespace pds {

class ActiveScan {
public:
    // Sites per step: a few microseconds of reads, short beside a batch of
    // insertions.
    static constexpr std::size_t kStep = 2048;

    // Starts a scan of the whole list, whose bounds are in `tree`.
    void begin(std::vector<SiteIndex>& active, const FreeAreaTree& tree) {
        active_ = &active;
        tree_ = &tree;
        end_ = active.size();
        read_ = kept_ = 0;
        total_ = 0.0;
    }
    bool begun() const { return active_ != nullptr; }
    // One step; false once the whole list has been read.
    bool step() {
        std::vector<SiteIndex>& active = *active_;
        const std::size_t stop = read_ + kStep < end_ ? read_ + kStep : end_;
        for (; read_ < stop; ++read_) {
            const SiteIndex s = active[read_];
            const double w = tree_->weight(s);
            if (w > 0.0) {
                active[kept_++] = s;
                total_ += w;
            }
        }
        return read_ < end_;
    }
    // The scan finished: the list shrunk to the kept sites; returns the sum
    // of their bounds.
    double take() {
        while (step()) {
        }
        active_->resize(kept_);
        active_ = nullptr;
        return total_;
    }
    // The scan ended where it stands: the sites not yet read move down
    // behind the kept ones, in order.
    void seal() {
        if (!active_) return;
        std::vector<SiteIndex>& active = *active_;
        if (kept_ != read_) {
            for (std::size_t i = read_; i < end_; ++i) active[kept_ + (i - read_)] = active[i];
            active.resize(kept_ + (end_ - read_));
        }
        active_ = nullptr;
    }
    // Forgets the scan: the list is about to be emptied.
    void drop() { active_ = nullptr; }

private:
    std::vector<SiteIndex>* active_ = nullptr;  // while a scan is begun
    const FreeAreaTree* tree_ = nullptr;
    std::size_t end_ = 0, read_ = 0, kept_ = 0;
    double total_ = 0.0;
};

}  // namespace pds

#endif
