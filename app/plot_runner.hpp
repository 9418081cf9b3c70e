// Draws a run's plots with scripts/plot_run.py and a batch's with
// scripts/plot_report.py (Debian's python3 and
// matplotlib, /usr/bin/python3 first because the python3 first on PATH may
// not see Debian's packages). Not real-time; called after a run.
#pragma once

#include <string>

namespace handover::app {

/// Runs the plotter on DIR (which holds log.csv). Returns its exit code
/// (127 when no python could be started); its output goes to our stdout/stderr.
int drawPlots(const std::string& dir, bool quiet);

/// Draws DIR/report.png from a batch's DIR/results.csv (scripts/plot_report.py).
int drawReportPlot(const std::string& dir, bool quiet);

/// Runs scripts/NAME with DIR as its argument; its exit code (127: no python).
int runPlotScript(const std::string& name, const std::string& dir, bool quiet);

}  // namespace handover::app
