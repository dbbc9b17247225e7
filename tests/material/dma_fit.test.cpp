// Prony series fitted to DMA data (docs/materials.md; docs/theory.md (R14)) and the NNLS under it.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>
#include <viscoroll/material/dma_fit.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_dma_fit {

namespace {

const std::filesystem::path data_dir =
    std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "examples/data";

// The spectrum of examples/make_dma_data.cpp: rho_j = 10^(-8 + 11 j/19) s, j = 0..19.
std::vector<double> generating_times() {
  std::vector<double> t;
  for (int j = 0; j < 20; ++j) t.push_back(std::pow(10.0, -8.0 + 11.0 * j / 19.0));
  return t;
}

double worst_error(const viscoroll::DmaFit<double>& fit, const viscoroll::DmaData<double>& data) {
  const double two_pi = 2 * std::acos(-1.0);
  double e = 0;
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const double w = two_pi * fit.report.reduced_frequency_hz[i];
    e = std::max(e, std::abs(fit.material.storage_modulus(w) / data.points[i].storage - 1));
    e = std::max(e, std::abs(fit.material.loss_modulus(w) / data.points[i].loss - 1));
  }
  return e;
}

}  // namespace

TEST_CASE("nnls: Lawson-Hanson recovers a known solution with active constraints",
          "[material][dma]") {
  using Matrix = Eigen::MatrixXd;
  using Vector = Eigen::VectorXd;
  // Hand example: min ||A x - b||, x >= 0; the unconstrained solution (-1, 2) is infeasible, the
  // constrained one x = (0, b.a2 / |a2|^2) = (0, 1.6).
  {
    Matrix a(3, 2);
    a << 1, 1, 0, 1, 1, 2;
    Vector b(3);
    b << 1, 2, 3;
    const Vector xu = a.colPivHouseholderQr().solve(b);
    REQUIRE(xu(0) < 0);
    const auto r = viscoroll::detail::nnls<double>(a, b);
    CHECK(r.converged);
    CHECK(r.x(0) == 0.0);
    CHECK(r.x(1) == Approx(9.0 / 6.0).epsilon(1e-14));
  }
  // Constructed Kuhn–Tucker point: x* with zeros on Z, b = A x* - y where y is orthogonal to
  // the columns on P and A_Z^T y = 1 (so the gradient A^T (b - A x*) is -1 on Z, 0 on P).
  std::mt19937 gen(7);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 5; ++trial) {
    const int m = 40, n = 12;
    Matrix a(m, n);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < n; ++j) a(i, j) = normal(gen);
    Vector x = Vector::Zero(n);
    std::vector<int> p, z;
    for (int j = 0; j < n; ++j) (j % 3 == 0 ? z : p).push_back(j);
    for (int j : p) x(j) = 0.5 + std::abs(normal(gen));
    Matrix ap(m, Eigen::Index(p.size())), az(m, Eigen::Index(z.size()));
    for (std::size_t k = 0; k < p.size(); ++k) ap.col(Eigen::Index(k)) = a.col(p[k]);
    for (std::size_t k = 0; k < z.size(); ++k) az.col(Eigen::Index(k)) = a.col(z[k]);
    const Eigen::HouseholderQR<Matrix> qr(ap);
    const Matrix q = qr.householderQ() * Matrix::Identity(m, Eigen::Index(p.size()));
    const Matrix mz = az - q * (q.transpose() * az);  // (I - Q Q^T) A_Z
    const Vector y = mz * (mz.transpose() * mz).ldlt().solve(Vector::Ones(Eigen::Index(z.size())));
    const Vector b = a * x - y;
    const auto r = viscoroll::detail::nnls<double>(a, b);
    CHECK(r.converged);
    CHECK((r.x - x).norm() <= 1e-12 * x.norm());
    for (int j : z) CHECK(r.x(j) == 0.0);
  }
}

TEST_CASE("dma: the CSV reader and its errors", "[material][dma]") {
  std::istringstream ok(
      "# a comment\n"
      "loss_pa, frequency_hz ,storage_pa,temperature_c\n"
      "\n"
      "2e5,1.5,3e6,25\n"
      "3e5,15,4e6,-10.5\n");
  const auto d = viscoroll::read_dma_csv<double>(ok);
  REQUIRE(d.points.size() == 2);
  CHECK(d.has_temperature);
  CHECK(d.points[1].frequency_hz == 15.0);
  CHECK(d.points[1].storage == 4e6);
  CHECK(d.points[1].loss == 3e5);
  CHECK(d.points[1].temperature_c == -10.5);
  std::istringstream tensile("frequency_hz,storage_pa,loss_pa\n1,3e6,3e5\n");
  const auto t = viscoroll::read_dma_csv<double>(tensile, {viscoroll::DmaModulus::tensile, 0.5});
  CHECK(t.points[0].storage == Approx(1e6).epsilon(1e-15));  // G = E / (2 (1 + nu))
  CHECK_FALSE(t.has_temperature);
  auto fails = [](const std::string& text) {
    std::istringstream in(text);
    return viscoroll::read_dma_csv<double>(in, {}, "x.csv");
  };
  CHECK_THROWS_WITH(fails("1,2,3\n"),
                    Catch::Contains("x.csv line 1") && Catch::Contains("unknown column '1'"));
  CHECK_THROWS_WITH(fails("frequency_hz,storage_pa\n1,2\n"),
                    Catch::Contains("lacks the column loss_pa"));
  CHECK_THROWS_WITH(fails("frequency_hz,storage_pa,loss_pa\n1,2\n"),
                    Catch::Contains("line 2: 2 fields"));
  CHECK_THROWS_WITH(fails("frequency_hz,storage_pa,loss_pa\n1,2,abc\n"),
                    Catch::Contains("loss_pa 'abc' is not a number"));
  CHECK_THROWS_WITH(
      fails("frequency_hz,storage_pa,loss_pa\n1,2,3\n-1,2,3\n"),
      Catch::Contains("line 3: frequency_hz = -1 is outside the valid range frequency_hz > 0"));
  CHECK_THROWS_WITH(fails("frequency_hz,storage_pa,loss_pa\n"), Catch::Contains("no data rows"));
  CHECK_THROWS_AS(viscoroll::read_dma_csv_file<double>(data_dir / "no_such.csv"),
                  std::invalid_argument);
}

TEST_CASE("dma: the fit recovers the known spectrum's moduli to 1e-6 at every frequency",
          "[material][dma]") {
  const auto data = viscoroll::read_dma_csv_file<double>(data_dir / "dma_known_spectrum.csv");
  REQUIRE(data.points.size() == 141);
  // Fit times that include the generating times: the spectrum itself is a feasible point with
  // zero residual, so NNLS reaches rounding.
  viscoroll::DmaFitOptions<double> options;
  options.times = generating_times();
  const auto fit = viscoroll::fit_prony(data, options);
  INFO(fit.report.summary);
  CHECK_FALSE(fit.report.poor);
  CHECK(fit.report.max_storage_error <= 1e-6);
  CHECK(fit.report.max_loss_error <= 1e-6);
  CHECK(worst_error(fit, data) <= 1e-6);
  CHECK(fit.material.g_inf() == Approx(1e6).epsilon(1e-6));
  WARN("known spectrum, generating times: " << fit.report.summary);
  // The automatic grid (2 per decade, not the generating times): the error is reported.
  const auto auto_fit = viscoroll::fit_prony(data, viscoroll::DmaFitOptions<double>{});
  INFO(auto_fit.report.summary);
  CHECK_FALSE(auto_fit.report.poor);
  CHECK(auto_fit.report.max_storage_error <= 0.02);
  CHECK(auto_fit.report.max_loss_error <= 0.02);
  WARN("known spectrum, automatic grid: " << auto_fit.report.summary);
}

TEST_CASE("dma: data at several temperatures are shifted to the master curve first",
          "[material][dma]") {
  const auto data = viscoroll::read_dma_csv_file<double>(data_dir / "dma_known_spectrum_wlf.csv");
  REQUIRE(data.has_temperature);
  viscoroll::DmaFitOptions<double> options;
  options.times = generating_times();
  CHECK_THROWS_WITH(viscoroll::fit_prony(data, options), Catch::Contains("shift"));
  options.shift = viscoroll::WlfShift<double>(8.86, 101.6, 20.0);
  const auto fit = viscoroll::fit_prony(data, options);
  INFO(fit.report.summary);
  CHECK_FALSE(fit.report.poor);
  CHECK(worst_error(fit, data) <= 1e-6);
  CHECK(fit.report.reduced_frequency_hz.front() ==
        Approx(0.01 * viscoroll::shift_factor(*options.shift, -30.0)));
}

TEST_CASE("dma: a poor fit is reported, not hidden; no rubbery plateau is an error",
          "[material][dma]") {
  const auto data = viscoroll::read_dma_csv_file<double>(data_dir / "dma_known_spectrum.csv");
  viscoroll::DmaFitOptions<double> options;
  options.times = {1e-6, 1e-2};  // two times for twelve decades
  const auto fit = viscoroll::fit_prony(data, options);
  CHECK(fit.report.poor);
  CHECK(fit.report.max_loss_error > 0.5);
  CHECK(fit.report.rms_loss_error > 0.1);
  CHECK(fit.report.nonzero_terms <= 2);
  CHECK_THAT(fit.report.summary, Catch::StartsWith("POOR FIT"));
  // A Maxwell fluid (storage modulus falling as f^2 to zero): G_inf = 0 from NNLS.
  viscoroll::DmaData<double> fluid;
  for (int k = 0; k <= 40; ++k) {
    const double f = std::pow(10.0, -3.0 + k / 10.0), u = 2 * std::acos(-1.0) * f * 1.0;
    fluid.points.push_back({f, 1e6 * u * u / (1 + u * u), 1e6 * u / (1 + u * u), 0.0});
  }
  CHECK_THROWS_WITH(viscoroll::fit_prony(fluid, viscoroll::DmaFitOptions<double>{}),
                    Catch::Contains("g_inf = 0") && Catch::Contains("no rubbery plateau"));
}

}  // namespace test_dma_fit
