#include "TileInterpolator.h"

#include <cassert>
#include <cmath>
#include <utility>

namespace tessera::subdiv::detail {

void TileInterpolator::tridiagonal(bool low, bool high, double* z, size_t stride, std::span<double> rhs) const {
    const uint32_t n = mN;
    // Row i: a z[i] + b z[i+1] + c z[i+2]; an extrapolated end folds into
    // its row: (2 z1 - z2) + 6 z1 + z2 = 8 z1.
    const auto a = [&](uint32_t i) { return i == n - 1 && high ? 0.0 : 1.0; };
    const auto b = [&](uint32_t i) { return (i == 0 && low) || (i == n - 1 && high) ? 8.0 : 6.0; };
    const auto c = [&](uint32_t i) { return i == 0 && low ? 0.0 : 1.0; };
    if (!low) rhs[0] -= z[0];
    if (!high) rhs[n - 1] -= z[(n + 1) * stride];
    // Thomas algorithm (diagonally dominant: no pivoting needed).
    std::vector<double> forward(n);
    forward[0] = c(0) / b(0);
    rhs[0] /= b(0);
    for (uint32_t i = 1; i < n; ++i) {
        const double m = b(i) - a(i) * forward[i - 1];
        forward[i] = c(i) / m;
        rhs[i] = (rhs[i] - a(i) * rhs[i - 1]) / m;
    }
    z[n * stride] = rhs[n - 1];
    for (uint32_t i = n - 1; i-- > 0;) z[(i + 1) * stride] = rhs[i] - forward[i] * z[(i + 2) * stride];
}

void TileInterpolator::solve(std::span<double> grid, std::span<const double> samples,
                             std::span<const PinnedCoefficient> pins, std::array<bool, 4> extrapolated) const {
    const uint32_t n = mN, side = n + 2;
    assert(grid.size() == size_t(side) * side && samples.size() == size_t(n) * n && pins.size() <= 4);
    const bool left = extrapolated[3], right = extrapolated[1], bottom = extrapolated[0], top = extrapolated[2];
    const auto g = [&](uint32_t x, uint32_t y) -> double& { return grid[size_t(y) * side + x]; };
    // E[y][x] = (D[y][x-1] + 6 D[y][x] + D[y][x+1]) / 8: from the ring on
    // rows 0 and n+1 where they are given; S = (E[y-1] + 6 E[y] + E[y+1]) / 8
    // gives the rest.
    std::vector<double> e(size_t(side) * n), rhs(n);
    const auto rowSum = [&](uint32_t x, uint32_t y) { return (g(x - 1, y) + 6.0 * g(x, y) + g(x + 1, y)) / 8.0; };
    for (uint32_t x = 1; x <= n; ++x) {
        e[x - 1] = rowSum(x, 0);
        e[size_t(n + 1) * n + x - 1] = rowSum(x, n + 1);
        for (uint32_t y = 1; y <= n; ++y) rhs[y - 1] = 8.0 * samples[size_t(y - 1) * n + x - 1];
        tridiagonal(bottom, top, e.data() + (x - 1), n, rhs);
    }
    for (uint32_t y = 1; y <= n; ++y) {
        for (uint32_t x = 1; x <= n; ++x) rhs[x - 1] = 8.0 * e[size_t(y) * n + x - 1];
        tridiagonal(left, right, &g(0, y), 1, rhs);
    }
    if (pins.empty()) return;
    // A unit change of sample (qx, qy) moves coefficient (x, y) by
    // 64 X[x][qx] Y[y][qy], X and Y the inverses of the two axes' matrices;
    // pins sit at corners, so columns 1 and n of each suffice. Find the
    // sample changes that move the pinned coefficients onto their values.
    std::array<std::vector<double>, 4> columns; // X col 1, X col n, Y col 1, Y col n (1-based z, zero ends)
    for (uint32_t k = 0; k < 4; ++k) {
        columns[k].assign(side, 0.0);
        std::fill(rhs.begin(), rhs.end(), 0.0);
        rhs[k % 2 == 0 ? 0 : n - 1] = 1.0;
        if (k < 2)
            tridiagonal(left, right, columns[k].data(), 1, rhs);
        else
            tridiagonal(bottom, top, columns[k].data(), 1, rhs);
    }
    const auto response = [&](glm::uvec2 at, glm::uvec2 sample) {
        return 64.0 * columns[sample.x == 1 ? 0 : 1][at.x] * columns[sample.y == 1 ? 2 : 3][at.y];
    };
    const size_t m = pins.size();
    double a[4][5] = {};
    for (size_t i = 0; i < m; ++i) {
        for (size_t j = 0; j < m; ++j) a[i][j] = response(pins[i].texel, pins[j].texel);
        a[i][4] = pins[i].value - g(pins[i].texel.x, pins[i].texel.y);
    }
    for (size_t col = 0; col < m; ++col) { // Gauss-Jordan, partial pivoting
        size_t pivot = col;
        for (size_t r = col + 1; r < m; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        std::swap(a[col], a[pivot]);
        for (size_t r = 0; r < m; ++r) {
            if (r == col) continue;
            const double f = a[r][col] / a[col][col];
            for (size_t c = col; c < 5; ++c) a[r][c] -= f * a[col][c];
        }
    }
    for (size_t j = 0; j < m; ++j) {
        const double change = a[j][4] / a[j][j];
        for (uint32_t y = 1; y <= n; ++y)
            for (uint32_t x = 1; x <= n; ++x) g(x, y) += change * response({x, y}, pins[j].texel);
    }
    for (const PinnedCoefficient& pin : pins) g(pin.texel.x, pin.texel.y) = pin.value; // exactly
}

} // namespace tessera::subdiv::detail
