#include "app/render/body_drag.hpp"

namespace handover::render {

BodyDrag::BodyDrag() {
  mjv_defaultPerturb(&perturb_);
  mju_zero3(ref_to_body_pos_);
  mju_unit4(ref_to_body_quat_);
}

void BodyDrag::select(const mjModel* m, mjData* d, int body, const mjtNum grab_point[3]) {
  if (active()) end(m, d);
  if (body <= 0 || body >= m->nbody) {
    perturb_.select = 0;
    return;
  }
  perturb_.select = body;
  perturb_.skinselect = -1;
  // grab point in body coordinates: where the spring attaches / rotation pivots
  mjtNum offset[3] = {0, 0, 0};
  if (grab_point != nullptr) mju_sub3(offset, grab_point, d->xpos + 3 * body);
  mju_mulMatTVec(perturb_.localpos, d->xmat + 9 * body, offset, 3, 3);
}

bool BodyDrag::begin(const mjModel* m, const mjData* d, const mjvScene* scene, int pert_bit) {
  const int body = perturb_.select;
  if (body <= 0) return false;
  mjv_initPerturb(m, d, scene, &perturb_);
  perturb_.active = pert_bit;

  // Whatever reference frame initPerturb chose (body origin or centre of
  // mass), remember where the body origin sits in it, so a mocap body moves
  // rigidly with the reference and does not jump at the first motion.
  mjtNum ref_conj[4], delta[3];
  mju_negQuat(ref_conj, perturb_.refquat);
  mju_sub3(delta, d->xpos + 3 * body, perturb_.refpos);
  mju_rotVecQuat(ref_to_body_pos_, delta, ref_conj);
  mju_mulQuat(ref_to_body_quat_, ref_conj, d->xquat + 4 * body);

  const int mocap = m->body_mocapid[body];
  if (mocap >= 0) {
    DraggedPose pose;
    pose.body = body;
    pose.mocap = mocap;
    const char* name = mj_id2name(m, mjOBJ_BODY, body);
    pose.name = name ? name : "";
    mju_copy3(pose.pos, d->xpos + 3 * body);
    mju_copy4(pose.quat, d->xquat + 4 * body);
    pose.dragging = true;
    held_ = pose;
  }
  return true;
}

void BodyDrag::move(const mjModel* m, const mjData* d, const mjvScene* scene, int action,
                    mjtNum reldx, mjtNum reldy) {
  if (!active()) return;
  mjv_movePerturb(m, d, action, reldx, reldy, scene, &perturb_);
  if (held_ && held_->body == perturb_.select) {
    // body pose = reference pose * (body in reference frame)
    mjtNum rotated[3];
    mju_rotVecQuat(rotated, ref_to_body_pos_, perturb_.refquat);
    mju_add3(held_->pos, perturb_.refpos, rotated);
    mju_mulQuat(held_->quat, perturb_.refquat, ref_to_body_quat_);
    mju_normalize4(held_->quat);
  }
}

void BodyDrag::end(const mjModel* m, mjData* d) {
  perturb_.active = 0;
  if (held_) held_->dragging = false;
  clearForce(m, d);
}

void BodyDrag::apply(const mjModel* m, mjData* d) {
  if (held_ && held_->mocap >= 0 && held_->mocap < m->nmocap) {
    mju_copy3(d->mocap_pos + 3 * held_->mocap, held_->pos);
    mju_copy4(d->mocap_quat + 4 * held_->mocap, held_->quat);
  }
  const int body = perturb_.select;
  if (active() && body > 0 && m->body_mocapid[body] < 0) {
    clearForce(m, d);
    mjv_applyPerturbForce(m, d, &perturb_);
    force_body_ = body;
  }
}

void BodyDrag::clearForce(const mjModel* m, mjData* d) {
  if (force_body_ > 0 && force_body_ < m->nbody) mju_zero(d->xfrc_applied + 6 * force_body_, 6);
  force_body_ = -1;
}

}  // namespace handover::render
