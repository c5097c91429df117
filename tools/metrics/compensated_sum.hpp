// Neumaier's compensated summation: the metrics sum millions of terms (in an order that
// nth_element leaves unspecified), and the tests hold them to 1e-12 relative.
#pragma once

#include <cmath>

namespace vkw::metrics {

class CompensatedSum {
public:
    void add(double x) {
        const double t = sum_ + x;
        // Whichever operand is larger lost the low bits of the other; keep them.
        correction_ += std::abs(sum_) >= std::abs(x) ? (sum_ - t) + x : (x - t) + sum_;
        sum_ = t;
    }
    double value() const { return sum_ + correction_; }

private:
    double sum_ = 0.0;
    double correction_ = 0.0;
};

}  // namespace vkw::metrics
