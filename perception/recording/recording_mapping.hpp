// A recording mapping: how a motion-capture recording in someone else's
// conventions becomes our tracked stream (docs/recordings.md). Read from a
// small YAML file, validated strictly (errors name file, key and line).
// Lengths in the mapping are in metres; only the data uses `units`.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace handover::perception::recording {

/// A signed axis of a body frame or of the recording's world, e.g. "-x".
struct SignedAxis {
  int index = 0;    ///< 0 = x, 1 = y, 2 = z
  double sign = 1;  ///< +1 or -1
  Eigen::Vector3d vector() const { return sign * Eigen::Vector3d::Unit(index); }
};

/// Where one tracked body's numbers are: a file (relative to the data folder)
/// and the header names of its 3 position and 4 quaternion columns, the
/// latter in the quaternion order of the mapping.
struct BodyColumns {
  std::string file;
  std::vector<std::string> position;    ///< 3 column names
  std::vector<std::string> quaternion;  ///< 4 column names, in `quaternion_order`
};

/// One recorded bone: origin at its proximal joint, long axis toward the
/// next joint along a local signed axis.
struct BoneMapping {
  BodyColumns columns;
  SignedAxis long_axis;
};

/// The hand: origin at the wrist; the grip point (palm centre) lies `grip`
/// metres from it along the long axis; `back_axis` points out of the back of
/// the hand (our hand z).
struct HandMapping {
  BodyColumns columns;
  SignedAxis long_axis;
  SignedAxis back_axis;
  double grip = 0.0;  ///< m, wrist to grip point
};

/// The object: its own tracked body (origin at its centre, `long_axis` its
/// symmetry axis, our object z), or the hand frame times a fixed offset.
struct ObjectMapping {
  bool tracked = false;
  BodyColumns columns;                                           ///< when tracked
  SignedAxis long_axis{2, 1.0};                                  ///< when tracked
  Eigen::Isometry3d in_hand = Eigen::Isometry3d::Identity();    ///< when not tracked: object in our hand frame
  std::string shape;               ///< cylinder | box | sphere, "" = not stated
  std::vector<double> size;        ///< m, as in a scenario's object.size
};

/// How the recording is put into the robot's world (after units and up axis).
struct Placement {
  /// true: a rigid transform `transform`; false: the receiver is put where
  /// the robot stands and the giver across the table (+x), floor on ours.
  bool rigid = false;
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  BodyColumns receiver;  ///< a body of the receiver (e.g. the hip), its mean over the window
  BodyColumns giver;     ///< a body of the giver, the same way
  double floor = 0.0;    ///< m, floor height in the recording, along its up axis
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();  ///< m, added in our world afterwards
};

struct RecordingMapping {
  std::string file;  ///< the mapping file (for messages)
  double rate_hz = 0.0;              ///< rows per second (used when no time column)
  std::string time_column;           ///< column with the stamp in s, "" = rows at rate_hz
  double units = 1.0;                ///< metres per data unit (m: 1, cm: 0.01, mm: 0.001)
  SignedAxis up{2, 1.0};             ///< the recording's up axis
  bool scalar_first = false;         ///< quaternion order: wxyz (true) or xyzw (false)
  HandMapping hand;
  BoneMapping forearm;
  BoneMapping upper_arm;
  ObjectMapping object;
  Placement place;
  double window_start = 0.0;                ///< s of the recording
  std::optional<double> window_end;         ///< s of the recording, unset = to the end
  double speed = 1.0;                       ///< playback speed (2 = twice as fast)
  bool mirror = false;                      ///< swap left and right (reflect y in our world)
  double hold_end = 0.0;                    ///< s, the last pose repeated after the window
  std::string data_dir;                     ///< default data folder, relative to the mapping file
};

/// Reads and validates a mapping file; throws InputError naming file, key and line.
RecordingMapping loadRecordingMapping(const std::string& path);

/// The same from text (tests); `origin` names it in messages, `base_dir`
/// resolves a relative `data` folder.
RecordingMapping parseRecordingMapping(const std::string& text, const std::string& origin,
                                       const std::string& base_dir = ".");

}  // namespace handover::perception::recording
