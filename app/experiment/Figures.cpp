#include "app/experiment/Figures.hpp"

#include <cairo.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <spawn.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include "common/nao/NaoFacts.hpp"

extern char** environ;

namespace simswift::experiment {

namespace {

constexpr double kPxPerM = 80;    // image scale
constexpr double kCell = 0.10;    // m, heat-map cell

struct Rgb {
  double r, g, b;
};
// Robot colours in setup order (distinct on green).
const Rgb kColours[] = {{0.90, 0.10, 0.10}, {0.15, 0.35, 0.95}, {1.00, 0.85, 0.10}, {0.75, 0.20, 0.85},
                        {0.00, 0.85, 0.85}, {1.00, 0.55, 0.00}};
Rgb colour(size_t i) { return kColours[i % (sizeof kColours / sizeof kColours[0])]; }

}  // namespace

bool runGnuplot(const std::string& dir, const std::string& name, const std::string& what, std::string* message) {
  const std::string base = dir + "/" + name;
  const std::string gp = base + ".gp", gp_name = name + ".gp";
  pid_t pid;
  char* argv[] = {const_cast<char*>("gnuplot"), const_cast<char*>(gp_name.c_str()), nullptr};
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addchdir_np(&fa, dir.c_str());
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, (name + ".gnuplot.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int rc = posix_spawnp(&pid, "gnuplot", &fa, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    *message = "gnuplot not found: " + what + " skipped (install gnuplot-nox; data in " + base + ".dat)";
    return false;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    *message = "gnuplot failed on " + gp + " (see " + base + ".gnuplot.log)";
    return false;
  }
  unlink((base + ".gnuplot.log").c_str());
  return true;
}

void drawRoutes(const Experiment& e, int setup, const std::vector<RouteSamples>& robots, const std::string& png) {
  const FieldConfig& f = e.field;
  const double L = f.carpetLength(), W = f.carpetWidth();
  const int width = static_cast<int>(std::lround(L * kPxPerM)), height = static_cast<int>(std::lround(W * kPxPerM));
  const int legend = 28;  // px below the carpet for the legend
  cairo_surface_t* surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height + legend);
  cairo_t* cr = cairo_create(surf);
  // Field frame (m) to pixels: x right, y up.
  auto px = [&](double x) { return (x + L / 2) * kPxPerM; };
  auto py = [&](double y) { return (W / 2 - y) * kPxPerM; };

  cairo_set_source_rgb(cr, 0.10, 0.45, 0.15);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_SQUARE);
  for (const LineSegment& l : f.lines) {
    cairo_set_line_width(cr, l.width * kPxPerM);
    cairo_move_to(cr, px(l.ax), py(l.ay));
    cairo_line_to(cr, px(l.bx), py(l.by));
    cairo_stroke(cr);
  }
  for (const LineCircle& c : f.circles) {
    cairo_set_line_width(cr, c.width * kPxPerM);
    cairo_new_sub_path(cr);
    cairo_arc(cr, px(c.cx), py(c.cy), c.radius * kPxPerM, 0, 2 * M_PI);
    cairo_stroke(cr);
  }
  for (const LineCross& c : f.crosses) {
    cairo_set_line_width(cr, c.width * kPxPerM);
    cairo_move_to(cr, px(c.x - c.size / 2), py(c.y));
    cairo_line_to(cr, px(c.x + c.size / 2), py(c.y));
    cairo_move_to(cr, px(c.x), py(c.y - c.size / 2));
    cairo_line_to(cr, px(c.x), py(c.y + c.size / 2));
    cairo_stroke(cr);
  }
  // Goals: the net's outline behind each goal line.
  const double gw = f.goal.inner_width / 2 + f.goal.post_diameter / 2;
  cairo_set_line_width(cr, 2);
  for (double side : {-1.0, 1.0}) {
    const double gx = side * f.length / 2;
    cairo_rectangle(cr, px(std::min(gx, gx + side * f.goal.depth)), py(gw), f.goal.depth * kPxPerM, 2 * gw * kPxPerM);
    cairo_stroke(cr);
  }

  // Heat maps: per robot, sample counts per 10 cm cell; opacity grows with
  // the log of the count so rarely visited cells still show.
  const int nx = static_cast<int>(std::ceil(L / kCell)), ny = static_cast<int>(std::ceil(W / kCell));
  for (size_t k = 0; k < robots.size(); ++k) {
    std::vector<int> count(static_cast<size_t>(nx) * ny, 0);
    int most = 0;
    for (const auto& [x, y] : robots[k].xy) {
      const int i = static_cast<int>(std::floor((x + L / 2) / kCell)), j = static_cast<int>(std::floor((W / 2 - y) / kCell));
      if (i < 0 || j < 0 || i >= nx || j >= ny) continue;
      most = std::max(most, ++count[static_cast<size_t>(j) * nx + i]);
    }
    const Rgb c = colour(k);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int n = count[static_cast<size_t>(j) * nx + i];
        if (!n) continue;
        const double a = 0.25 + 0.7 * std::log1p(n) / std::log1p(most);
        cairo_set_source_rgba(cr, c.r, c.g, c.b, a);
        cairo_rectangle(cr, i * kCell * kPxPerM, j * kCell * kPxPerM, kCell * kPxPerM, kCell * kPxPerM);
        cairo_fill(cr);
      }
  }

  // Start poses (ringed, with a heading tick) and ball positions (numbered).
  const Setup& s = e.setups[setup];
  for (size_t k = 0; k < s.robots.size(); ++k) {
    const ExperimentRobot& r = s.robots[k];
    const Rgb c = colour(k);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_set_line_width(cr, 3);
    cairo_new_sub_path(cr);
    cairo_arc(cr, px(r.x), py(r.y), common::nao::kFootprintRadius / 1000 * kPxPerM, 0, 2 * M_PI);
    cairo_move_to(cr, px(r.x), py(r.y));
    cairo_line_to(cr, px(r.x + 0.3 * std::cos(r.theta)), py(r.y + 0.3 * std::sin(r.theta)));
    cairo_stroke(cr);
  }
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, 13);
  for (const BallPosition& b : e.balls) {
    cairo_set_source_rgb(cr, 0.3, 1.0, 0.3);
    cairo_new_sub_path(cr);
    cairo_arc(cr, px(b.x), py(b.y), std::max(4.0, f.ball.diameter / 2 * kPxPerM), 0, 2 * M_PI);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, px(b.x) + 6, py(b.y) - 6);
    cairo_show_text(cr, std::to_string(b.number).c_str());
  }
  // Legend.
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_rectangle(cr, 0, height, width, legend);
  cairo_fill(cr);
  double lx = 8;
  for (size_t k = 0; k < robots.size(); ++k) {
    const Rgb c = colour(k);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_rectangle(cr, lx, height + 8, 14, 14);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, lx + 18, height + 20);
    cairo_show_text(cr, robots[k].player.c_str());
    lx += 90;
  }
  cairo_move_to(cr, lx + 10, height + 20);
  cairo_show_text(cr, ("setup " + s.name + ": routes over all trials; green dots = ball positions").c_str());

  cairo_destroy(cr);
  const cairo_status_t st = cairo_surface_write_to_png(surf, png.c_str());
  cairo_surface_destroy(surf);
  if (st != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(png + ": cannot write PNG: " + cairo_status_to_string(st));
}

bool plotFindTimes(const Experiment& e, int setup, const std::vector<TrialResult>& results, const std::string& dir,
                   std::string* message) {
  const Setup& s = e.setups[setup];
  // gnuplot runs in `dir` with relative names, so the script is the same
  // whatever the results folder is called.
  const std::string name = "findtime_" + s.name;
  const std::string base = dir + "/" + name;
  {
    // One line per find: column (1-based, ball order), seconds.
    std::ofstream d(base + ".dat");
    d << "# column position seconds (finds of setup " << s.name << ")\n";
    bool any = false;
    for (size_t b = 0; b < e.balls.size(); ++b)
      for (const TrialResult& r : results)
        if (r.setup == s.name && r.position == e.balls[b].number && r.found) {
          d << b + 1 << " " << r.position << " " << fixed(r.seconds, 2) << "\n";
          any = true;
        }
    if (!any) d << "0 0 NaN\n";  // gnuplot needs a point; nothing drawn
  }
  {
    std::ofstream g(base + ".gp");
    // Columns in ball order; a tic says found/tests. Only columns with finds
    // get a box (gnuplot refuses an all-NaN boxplot).
    std::vector<int> with_finds, found(e.balls.size(), 0), tests(e.balls.size(), 0);
    for (size_t b = 0; b < e.balls.size(); ++b) {
      for (const TrialResult& r : results)
        if (r.setup == s.name && r.position == e.balls[b].number) {
          ++tests[b];
          found[b] += r.found ? 1 : 0;
        }
      if (found[b]) with_finds.push_back(static_cast<int>(b) + 1);
    }
    g << "set terminal pngcairo size 900,500 font 'sans,11'\n"
      << "set output '" << name << ".png'\n"
      << "set title 'Setup " << s.name << ": time to find the ball (finds only; limit " << fixed(e.time_limit, 0)
      << " s)'\n"
      << "set xlabel 'ball position (table 5.2), found/tests'\nset ylabel 'seconds (simulated)'\n"
      << "set yrange [0:" << fixed(e.time_limit * 1.05, 0) << "]\nset xrange [0.3:" << e.balls.size() + 0.7 << "]\n"
      << "set style fill solid 0.35 border -1\nset style boxplot outliers pointtype 7\nset style data boxplot\n"
      << "set boxwidth 0.5\nunset key\nset grid ytics\nset xtics (";
    for (size_t b = 0; b < e.balls.size(); ++b)
      g << (b ? ", " : "") << "'" << e.balls[b].number << " (" << found[b] << "/" << tests[b] << ")' " << b + 1;
    g << ")\n";
    if (with_finds.empty()) {
      g << "plot 1/0 notitle\n";
    } else {
      g << "plot";
      for (size_t k = 0; k < with_finds.size(); ++k)
        g << (k ? "," : "") << " '" << name << ".dat' using (" << with_finds[k] << "):($1==" << with_finds[k]
          << " ? $3 : NaN) lc rgb '#2060c0' pointsize 0.6";
      g << "\n";
    }
  }
  return runGnuplot(dir, name, "find-time box plots", message);
}

namespace {

// A gnuplot single-quoted string ('' is a quote).
std::string gpString(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

}  // namespace

bool plotSweep(const Experiment& e, const std::vector<CellRow>& rows, int axis, const std::string& dir,
               std::string* message) {
  const SweepAxis& a = e.sweep[axis];
  const std::string png = sweepFigureName(a);
  const std::string name = png.substr(0, png.size() - 4);
  const int n = static_cast<int>(a.values.size());
  // x: the values themselves when all are numbers, else 1..n with the values as tics.
  std::vector<double> x;
  bool numeric = true;
  for (const SweepValue& v : a.values) {
    char* end = nullptr;
    const double d = std::strtod(v.label.c_str(), &end);
    numeric = numeric && !v.label.empty() && *end == '\0' && std::isfinite(d);
    x.push_back(d);
  }
  if (!numeric)
    for (int i = 0; i < n; ++i) x[i] = i + 1;
  const double lo = *std::min_element(x.begin(), x.end()), hi = *std::max_element(x.begin(), x.end());
  const double span = hi > lo ? hi - lo : 1.0;

  // Series: one setup with one combination of the other paths' values, in
  // the order the cells table lists them.
  struct Series {
    int setup = 0;
    std::vector<int> others;                     // value index per axis, -1 at `axis`
    std::vector<const CellRow*> at;              // per value of `axis`
  };
  std::vector<Series> series;
  for (const CellRow& r : rows) {
    std::vector<int> choice = sweepChoice(e.sweep, r.cell);
    const int v = choice[axis];
    choice[axis] = -1;
    auto it = std::find_if(series.begin(), series.end(),
                           [&](const Series& s) { return s.setup == r.setup && s.others == choice; });
    if (it == series.end()) {
      series.push_back({r.setup, choice, std::vector<const CellRow*>(n, nullptr)});
      it = series.end() - 1;
    }
    it->at[v] = &r;
  }
  auto title = [&](const Series& s) {
    std::string t = "setup " + e.setups[s.setup].name;
    for (size_t k = 0; k < e.sweep.size(); ++k)
      if (s.others[k] >= 0) t += ", " + e.sweep[k].path + "=" + e.sweep[k].values[s.others[k]].label;
    return t;
  };

  const std::string base = dir + "/" + name;
  // One block per series (gnuplot's `index`): x (nudged per series so the
  // intervals do not hide each other), rate % and its interval, mean s and
  // its interval (NaN without finds: no point).
  std::vector<bool> any_rate(series.size(), false), any_time(series.size(), false);
  {
    std::ofstream d(base + ".dat");
    d << "# sweep of " << a.path << ": x rate_pct rate_lo rate_hi mean_s mean_lo mean_hi\n";
    for (size_t i = 0; i < series.size(); ++i) {
      const double nudge = (static_cast<double>(i) - (static_cast<double>(series.size()) - 1) / 2) * 0.012 * span;
      d << "# " << title(series[i]) << "\n";
      for (int v = 0; v < n; ++v) {
        const CellRow* r = series[i].at[v];
        d << fixed(x[v] + nudge, 6);
        if (r && r->tests) {
          d << " " << fixed(100.0 * r->found / r->tests, 3) << " " << fixed(100 * r->rate.lo, 3) << " "
            << fixed(100 * r->rate.hi, 3);
          any_rate[i] = true;
        } else {
          d << " NaN NaN NaN";
        }
        if (r && !r->times.empty()) {
          d << " " << fixed(r->mean_s, 3) << " " << fixed(r->mean_ci.lo, 3) << " " << fixed(r->mean_ci.hi, 3) << "\n";
          any_time[i] = true;
        } else {
          d << " NaN NaN NaN\n";
        }
      }
      d << "\n\n";
    }
  }
  {
    std::ofstream g(base + ".gp");
    g << "set terminal pngcairo noenhanced size 1200,500 font 'sans,10'\n"
      << "set output " << gpString(png) << "\n"
      << "set multiplot layout 1,2 title " << gpString("sweep of " + a.path + " (95 % intervals: Wilson for the rate, "
                                                      "bootstrap for the mean; limit " + fixed(e.time_limit, 0) + " s)")
      << "\nset xlabel " << gpString(a.path) << "\n"
      << "set xrange [" << fixed(lo - 0.1 * span, 6) << ":" << fixed(hi + 0.1 * span, 6) << "]\n"
      << "set grid\nset key below\nset bars small\n";
    if (!numeric) {
      g << "set xtics (";
      for (int v = 0; v < n; ++v) g << (v ? ", " : "") << gpString(a.values[v].label) << " " << v + 1;
      g << ")\n";
    }
    auto panel = [&](const std::string& ylabel, const std::string& yrange, int col, const std::vector<bool>& any) {
      g << "set ylabel " << gpString(ylabel) << "\nset yrange " << yrange << "\n";
      std::ostringstream p;
      for (size_t i = 0; i < series.size(); ++i)
        if (any[i])
          p << (p.str().empty() ? "plot" : ",") << " " << gpString(name + ".dat") << " index " << i << " using 1:"
            << col << ":" << col + 1 << ":" << col + 2 << " with yerrorlines lc " << i + 1 << " pt 7 title "
            << gpString(title(series[i]));
      g << (p.str().empty() ? "plot 1/0 notitle" : p.str()) << "\n";
    };
    panel("find rate (%)", "[0:105]", 2, any_rate);
    panel("mean find time over the finds (s, simulated)", "[0:" + fixed(e.time_limit * 1.05, 0) + "]", 5, any_time);
    g << "unset multiplot\n";
  }
  return runGnuplot(dir, name, "sweep plots", message);
}

}  // namespace simswift::experiment
