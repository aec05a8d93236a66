// Joint hydraulic apertures through the real program (docs/coupling.md, "Joint hydraulic
// apertures"): a closed joint conducts by its residual aperture whatever the mesh, and a joint
// under normal load follows the Barton–Bandis closure. Both in an all but impermeable matrix,
// where the right side's outflow is the joint's flow:
//   Q = (ρ g / μ) (a³ / 12) Δh / L,
// L the joint's length, Δh = 1 mm between the left and right sides (the parallel-plate law,
// Witherspoon et al. 1980), and the closure under an effective normal stress σn,
//   a = a_r + V_m − σn V_m / (k_ni V_m + σn)   (Barton, Bandis
// & Bakhtar 1985). Tolerances: the closed joint's flow within 2% on every mesh; the loaded
// joint's flow within 1%, its normal stress within 1% and its aperture within 0.5%; a fault of
// its own law beside joints of the default's, each by its own law, the same.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "../cli/result_files.hpp"
#include "../cli/run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::column;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;

namespace {

const fs::path kVerification = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification";
constexpr double kConductivityPerPermeability = 1000.0 * 9.81 / 1.0e-3;  // ρ g / μ
constexpr double kHeadDrop = 1.0e-3;                                      // m

struct Folder : hydrodda::testing::TemporaryFolder {
  explicit Folder(const std::string& name)
      : TemporaryFolder("hydrodda-joint-apertures-" + name + "-" + std::to_string(::getpid())) {}
};

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// `text` with the one occurrence of `from` replaced by `to` (the test fails when there is none).
std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

struct JointRun {
  nlohmann::json summary = nlohmann::json::object();
  std::vector<std::vector<std::string>> fractures;  // fractures.csv, header first
};

JointRun run_text(const std::string& scenario, const Folder& folder, const std::string& name) {
  const fs::path file = folder.path / (name + ".toml");
  fs::create_directories(folder.path);
  std::ofstream(file) << scenario;
  const fs::path out = folder.path / name;
  const auto result = run_program("-q run " + file.string() + " -o " + out.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  JointRun r;
  if (std::ifstream in(out / "summary.json"); in) r.summary = nlohmann::json::parse(in);
  r.fractures = read_csv(out / "fractures.csv");
  return r;
}

double right_outflow(const JointRun& r) { return r.summary["flow"]["boundaries"]["right"].get<double>(); }

// The last row's value of a fractures.csv column (one fracture: one row per pass).
double last_fracture_value(const JointRun& r, const std::string& name) {
  if (r.fractures.size() < 2) {
    ADD_FAILURE() << "fractures.csv has no rows";
    return NAN;
  }
  return std::stod(r.fractures.back()[column(r.fractures[0], name)]);
}

// One closed joint, residual aperture a = 0.1 mm, from (0, 0.3) to (1, 0.7) m: on meshes of
// 0.2, 0.1 and 0.05 m the outflow is (ρg/μ)(a³/12) Δh / L within 2% (the bound; the
// embedded transmissivity is exact for a head linear along the joint, so it comes out far
// closer), and fractures.csv reports the joint closed with that hydraulic aperture.
TEST(JointApertures, ClosedJointCarriesItsResidualApertureOnEveryMesh) {
  Folder folder("closed");
  const std::string base = read_text(kVerification / "coupled_closed_joint.toml");
  const double a = 1.0e-4, length = std::sqrt(1.16);
  const double expected = kConductivityPerPermeability * a * a * a / 12.0 * kHeadDrop / length;
  for (const std::string size : {"0.2", "0.1", "0.05"}) {
    std::string text = replace_once(replace_once(base, "size = 0.1\n", "size = " + size + "\n"),
                                    "fracture_size = 0.1\n", "fracture_size = " + size + "\n");
    if (size == "0.2") text = replace_once(text, "figures = []", "figures = [\"png\"]");
    const JointRun r = run_text(text, folder, "mesh" + size);
    // With the joint keys the figures add the apertures the flow sees.
    if (size == "0.2") {
      EXPECT_TRUE(fs::exists(folder.path / ("mesh" + size) / "figures/hydraulic_apertures.png"));
    }
    ASSERT_TRUE(r.summary.contains("flow")) << size;
    EXPECT_TRUE(r.summary["converged"].get<bool>()) << size;
    const double q = right_outflow(r);
    EXPECT_NEAR(q, expected, 0.02 * expected) << "mesh size " << size;
    std::printf("mesh %s m: outflow %.6e m2/s, expected %.6e (%+.3f%%)\n", size.c_str(), q, expected,
                100.0 * (q / expected - 1.0));
    EXPECT_EQ(last_fracture_value(r, "open"), 0.0) << size;
    EXPECT_NEAR(last_fracture_value(r, "hydraulic_aperture"), a, 1e-12) << size;
    // The flow along the joint is the outflow (it carries all of it).
    EXPECT_NEAR(last_fracture_value(r, "flow"), q, 1e-3 * q) << size;
  }
}

// The same closed joint seen by a [[flow.region]] over the whole square: the region's tensor
// comes from the tensors the flow was solved with. A straight joint of transmissivity
// T = (ρg/μ) a³/12 crossing the region leaves the linear heads of the tensor's two solves
// exact, so K = K_m I + T (L/A) t⊗t: its larger principal value K_m + T L (L = √1.16 m, A = 1 m²)
// along t = (1, 0.4)/L, its smaller the matrix's (1e-6 relative; the joint elements' largest
// principal value taken as an isotropic k had made both large).
TEST(JointApertures, ARegionsTensorFollowsTheJoint) {
  Folder folder("tensor");
  const std::string text = read_text(kVerification / "coupled_closed_joint.toml") +
                           "\n[[flow.region]]\nname = \"square\"\npolygon = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]\n";
  const JointRun r = run_text(text, folder, "tensor");
  ASSERT_TRUE(r.summary["converged"].get<bool>());
  const auto& region = r.summary["flow"]["regions"]["square"];
  const double k_m = region["matrix_conductivity"];
  const double a = 1.0e-4, length = std::sqrt(1.16);
  const double along = k_m + kConductivityPerPermeability * a * a * a / 12.0 * length;
  const auto& tensor = region["conductivity_tensor"];
  const double larger = std::max(double(tensor["principal_values"][0]), double(tensor["principal_values"][1]));
  const double smaller = std::min(double(tensor["principal_values"][0]), double(tensor["principal_values"][1]));
  EXPECT_NEAR(larger, along, 1e-6 * along);
  EXPECT_NEAR(smaller, k_m, 1e-6 * k_m);
  const int major = double(tensor["principal_values"][0]) >= double(tensor["principal_values"][1]) ? 0 : 1;
  const double dx = tensor["principal_directions"][major][0], dy = tensor["principal_directions"][major][1];
  EXPECT_NEAR(std::abs(dx * 0.4 - dy * 1.0) / length, 0.0, 1e-6);  // parallel to (1, 0.4)
}

// One joint loaded normally by σ = 0, 5, 10, 15, 20 MPa on the top (rollers elsewhere): its
// effective normal stress is σ, its hydraulic aperture the Barton–Bandis
//   a(σ) = a_r + V_m − σ V_m / (k_ni V_m + σ),   a_r = 1e-5 m, V_m = 1e-4 m, k_ni = 2e11 Pa/m,
// and the outflow (ρg/μ)(a³/12) Δh / 1 m within 1% at every load.
TEST(JointApertures, LoadedJointFollowsBartonBandisClosure) {
  Folder folder("closure");
  const std::string base = read_text(kVerification / "coupled_joint_closure.toml");
  const double residual = 1.0e-5, closure = 1.0e-4, stiffness = 2.0e11;
  double previous = INFINITY;
  for (const double sigma : {0.0, 5.0e6, 10.0e6, 15.0e6, 20.0e6}) {
    const std::string load = std::to_string(-sigma);
    const std::string text = replace_once(base, "normal = 0.0\n", "normal = " + load + "\n");
    const JointRun r = run_text(text, folder, "load" + std::to_string(static_cast<int>(sigma / 1e6)));
    ASSERT_TRUE(r.summary.contains("flow")) << sigma;
    EXPECT_TRUE(r.summary["converged"].get<bool>()) << sigma;
    const double a = residual + closure - sigma * closure / (stiffness * closure + sigma);
    const double expected = kConductivityPerPermeability * a * a * a / 12.0 * kHeadDrop;
    const double q = right_outflow(r);
    EXPECT_NEAR(q, expected, 0.01 * expected) << "σ = " << sigma << " Pa";
    EXPECT_LT(q, previous);
    previous = q;
    // fractures.csv: the effective normal stress is the load, the aperture the closure's.
    EXPECT_NEAR(last_fracture_value(r, "normal_stress"), sigma, 0.01 * sigma + 1.0) << sigma;
    EXPECT_NEAR(last_fracture_value(r, "hydraulic_aperture"), a, 0.005 * a) << sigma;
    std::printf("sigma %4.0f MPa: a %.4e m, outflow %.6e m2/s, expected %.6e (%+.3f%%), sigma_n %.6e Pa\n",
                sigma / 1e6, a, q, expected, 100.0 * (q / expected - 1.0), last_fracture_value(r, "normal_stress"));
    // summary.json's fractures section says the same at a glance.
    const nlohmann::json& f = r.summary["fractures"];
    EXPECT_EQ(f["count"].get<int>(), 1);
    EXPECT_EQ(f["open"].get<int>(), 0);
    EXPECT_NEAR(f["by_id"]["0"]["hydraulic_aperture"].get<double>(), last_fracture_value(r, "hydraulic_aperture"),
                1e-15);
  }
}

// The value of a fractures.csv column for one fracture in the last pass's rows.
double last_value_of(const JointRun& r, int fracture, const std::string& name) {
  for (std::size_t row = r.fractures.size(); row-- > 1;)
    if (std::stoi(r.fractures[row][column(r.fractures[0], "fracture")]) == fracture)
      return std::stod(r.fractures[row][column(r.fractures[0], name)]);
  ADD_FAILURE() << "fractures.csv has no row of fracture " << fracture;
  return NAN;
}

// A fault with its own hydraulic aperture law between two joints of the default law
// (coupled_fault_aperture.toml): three horizontal traces under σn = 1 MPa, each closed, each of
// aperture a(σn) = a_r + V_m − σn V_m / (k_ni V_m + σn) by its own type's keys (the fault's
// a_r and k_ni its own, its V_m [joint]'s), each carrying Q = (ρg/μ)(a³/12) Δh / 1 m, the
// parallel-plate law: fractures.csv's hydraulic_aperture within 0.5% and flow within 1% of them,
// the outflow within 1% of their sum (measured: 3e-9 and 1e-9 relative), and the type named.
TEST(JointApertures, AFaultCarriesItsOwnLawsFlow) {
  Folder folder("fault");
  const JointRun r = run_text(read_text(kVerification / "coupled_fault_aperture.toml"), folder, "fault");
  ASSERT_TRUE(r.summary.contains("flow"));
  EXPECT_TRUE(r.summary["converged"].get<bool>());
  const double sigma = 1.0e6;
  const auto aperture = [&](double residual, double stiffness, double closure) {
    return residual + closure - sigma * closure / (stiffness * closure + sigma);
  };
  const double joint = aperture(5.0e-5, 2.0e11, 1.0e-4), fault = aperture(4.0e-4, 1.0e10, 1.0e-4);
  const auto flow_of = [](double a) { return kConductivityPerPermeability * a * a * a / 12.0 * kHeadDrop; };
  // Fracture ids: the two listed joints (0, 1), then the [[geometry.fracture]] fault (2).
  double total = 0.0;
  for (const int id : {0, 1, 2}) {
    const double a = id == 2 ? fault : joint;
    const double q = flow_of(a);
    total += q;
    EXPECT_NEAR(last_value_of(r, id, "hydraulic_aperture"), a, 0.005 * a) << id;
    EXPECT_NEAR(last_value_of(r, id, "normal_stress"), sigma, 0.01 * sigma) << id;
    EXPECT_NEAR(last_value_of(r, id, "flow"), q, 0.01 * q) << id;
    EXPECT_EQ(last_value_of(r, id, "open"), 0.0) << id;
    std::printf("fracture %d: a %.6e m (expected %.6e), flow %.6e m2/s (expected %.6e, %+.2e)\n", id,
                last_value_of(r, id, "hydraulic_aperture"), a, last_value_of(r, id, "flow"), q,
                last_value_of(r, id, "flow") / q - 1.0);
  }
  EXPECT_NEAR(right_outflow(r), total, 0.01 * total);
  EXPECT_EQ(r.fractures.back()[column(r.fractures[0], "type")], "fault");
  EXPECT_EQ(r.summary["fractures"]["by_id"]["2"]["type"].get<std::string>(), "fault");
  EXPECT_EQ(r.summary["fractures"]["by_id"]["0"]["type"].get<std::string>(), "joint");
  std::printf("outflow %.6e m2/s, expected %.6e (%+.2e)\n", right_outflow(r), total, right_outflow(r) / total - 1.0);
}

// Without joint keys the porosity law alone: the closed joint's clipped gap (contact
// overlaps and slivers of the order of the penetration tolerance) conducts next to nothing,
// measured 1.1e-17 m²/s, twice the matrix's 5.5e-18 and 1.5e-8 of what its 0.1 mm residual
// aperture carries with the key; its hydraulic aperture is its mechanical one, 0.
TEST(JointApertures, WithoutJointKeysAClosedJointCarriesNextToNothing) {
  Folder folder("none");
  const std::string text =
      replace_once(replace_once(read_text(kVerification / "coupled_closed_joint.toml"), "residual_aperture = 1.0e-4\n", ""),
                   "figures = []", "figures = [\"png\"]");
  const JointRun r = run_text(text, folder, "none");
  ASSERT_TRUE(r.summary.contains("flow"));
  // Without them only the mechanical apertures' figure: the flow sees no other.
  EXPECT_TRUE(fs::exists(folder.path / "none/figures/apertures.png"));
  EXPECT_FALSE(fs::exists(folder.path / "none/figures/hydraulic_apertures.png"));
  // k_m = d² φ³ / (180 (1 − φ)²) = 5.6e-22 m²: (ρg/μ) k_m Δh over a 1 m square.
  const double k_matrix = 1.0e-10 * 1.0e-9 / (180.0 * 0.999 * 0.999);
  const double matrix_flow = kConductivityPerPermeability * k_matrix * kHeadDrop;
  const double a = 1.0e-4, joint_flow = kConductivityPerPermeability * a * a * a / 12.0 * kHeadDrop / std::sqrt(1.16);
  EXPECT_GE(right_outflow(r), matrix_flow * (1.0 - 1e-9));
  EXPECT_LT(right_outflow(r), 1e-6 * joint_flow);
  EXPECT_EQ(last_fracture_value(r, "hydraulic_aperture"), 0.0);
}

}  // namespace

namespace {

// A gap within the DDA's penetration tolerance counts as closed and takes the closure law's
// aperture under the face's stress, so the tolerance must resolve the joints' micrometres. The
// seal 1 km deep (tests/cli/scenarios/seal_at_depth.toml, a_r + V_m = 45 µm) at 600 m over its
// top: its default, a fiftieth of a_r + V_m (0.9 µm), and half that give K_eff/K_m within 0.5%
// (measured 2.70868 and 2.70877; a quarter of it, 2.7178, 0.3% above); the DDA's own 1e-4 of
// the allowed step displacement (15 µm) gave 2.6358, 2.7% lower, its seal base open along 1.8 m
// instead of 10.5 m.
TEST(JointApertures, ASealsConductivityIsSettledInThePenetrationTolerance) {
  Folder folder("tolerance");
  const std::string base = replace_once(read_text(fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/seal_at_depth.toml"),
                                        "head = 150.0", "head = 600.0") +
                           "\n[output]\nfigures = []\n";
  const auto conductivity = [&](const std::string& name, const std::string& tolerance) {
    const std::string text =
        tolerance.empty() ? base : replace_once(base, "steps = 20\n", "steps = 20\npenetration_tolerance = " + tolerance + "\n");
    const JointRun r = run_text(text, folder, name);
    EXPECT_TRUE(r.summary["converged"].get<bool>()) << name;
    return r.summary["flow"]["regions"]["seal"]["normalised_conductivity"].get<double>();
  };
  const double by_default = conductivity("default", "");
  const double halved = conductivity("halved", "4.5e-7");
  const double coarse = conductivity("coarse", "1.5e-5");
  EXPECT_NEAR(by_default, halved, 0.005 * halved);
  EXPECT_LT(coarse, 0.98 * halved);
  std::printf("K_eff/K_m: %.6g by default (0.9 um), %.6g at 0.45 um, %.6g at 15 um\n", by_default, halved, coarse);
}

}  // namespace
