// Turns a recording, described by its mapping, into our tracked stream:
// samples of the hand (grip point frame), forearm and upper arm, and of the
// object, in the robot's world (design notes 1), stamped from 0 at the start
// of the window. Start-up only (reads files, allocates).
#pragma once

#include <string>
#include <vector>

#include "perception/pose_sample.hpp"
#include "perception/recording/recording_mapping.hpp"

namespace handover::perception::recording {

/// Our world's floor height (design notes 1: the table top is z = 0, 0.75 m above the floor).
constexpr double kFloorHeight = -0.75;

struct ImportedRecording {
  std::vector<PoseSample> samples;  ///< in time order, stamps in s from 0
  /// The recording's world (data units scaled to metres) in ours, before any mirror.
  Eigen::Isometry3d world_T_recording = Eigen::Isometry3d::Identity();
  std::size_t recorded_rows = 0;  ///< rows taken from the window (the rest are held poses)
};

/// Reads the files of `mapping` from `data_dir` ("" = the mapping's `data`
/// folder) and converts them. Throws InputError naming the file, column or
/// mapping key on missing files or columns, files of different lengths, a
/// quaternion whose norm is off 1 by more than 1 %, or an empty window.
ImportedRecording importRecording(const RecordingMapping& mapping, const std::string& data_dir = "");

}  // namespace handover::perception::recording
