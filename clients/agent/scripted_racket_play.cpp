#include "scripted_racket_play.h"

namespace olympics::client::racket_play {

Play table_play() {
  Play p;
  p.sweet_spot = {0.45, -0.45, 0.15};
  // Balls met 0.25 m right of the root's line, not at the sweet spot 0.45 m right (issue 29,
  // sixth round): of the fed balls within reach, those met 0.35 m or more right of the root were
  // mostly returned short (not over), those within 0.3 m of its line mostly in; and the legs have
  // less far to step for a ball coming on the left. Tuning seeds 1-300 (ball return): returns in
  // 31.5% -> 37.5%; 1v1 seeds 1-20: strokes per point 1.25 -> 1.42. Met 0.15 m right: 41.2% in
  // ball return, but in 1v1 the feed, coming at the body, struck it more (body touch 264 -> 381
  // points) and strokes per point fell to 1.18 (docs/racket-sports.md).
  p.meet_spot = Eigen::Vector3d(0.45, -0.25, 0.15);
  // Between balls the player waits 0.43 m behind the table's end (each point starts 2 m back).
  // Of the opponent's returns that landed in 1v1 (tuning seeds 1-6, scripted on both sides), 14%
  // were short (0.3 m past the net) and bounced twice on the table before a player waiting 2 m
  // back got to them (1 of 162 feeds did); the receiver got to 54% of them against 64% of the
  // feeds. Waiting 1.8 m back: 1v1 tuning seeds 1-20, strokes per point 1.18 -> 1.51, points
  // with 4 or more 31 -> 85, falls 7 -> 2 (issue 29, the rally round; docs/racket-sports.md).
  p.home_x = -1.8;
  // ...and it walks there 0.6 s after its stroke, not 0.4 (issue 29, the recovery round). A
  // probe of 1v1 tuning seeds 1-4 found a player back from its stroke still 0.5 m nearer the
  // table than home, and hardly moving, when the opponent struck (0.9 s after its own stroke), so
  // walking sooner was tried first: at 0 / 0.2 s, seeds 1-20, strokes per point 1.51 -> 1.38 /
  // 1.40, falls 2 -> 8 / 8. Later paid: at 0.6 s, seeds 21-40, 1.54 -> 1.97, points of 4 or
  // more strokes 87 -> 163, falls 2 -> 6; unseen seeds 195001-195040, 1.49 -> 1.88, 4 or more
  // 9.9% -> 18.7%, falls 0.16 -> 0.06 a minute (docs/racket-sports.md; why, not traced).
  p.home_after_s = 0.6;
  // Returns land 0.45 m past the net, not 0.6 (issue 29, the passing balls). Of the balls that
  // passed the receiver untouched (1v1 tuning seeds 41-44: 35 of 595), 24 came to a receiver still
  // at the table's end from its last short ball, landing 0.3 m in front of it, where no contact
  // in front of the body clears the table; balls landing 0.4-0.6 m past the net were passed 0 of
  // 138 times, 0.6-1.0 m 32 of 289 (the 0.6 aim's median landing 0.66 m). Seeds 41-60: strokes
  // per point 3.11 -> 3.64, passed 25.7% -> 12.0% of points; 1.05 m: 1.82; walking home sooner:
  // 2.60 (docs/racket-sports.md).
  p.aim = {0.45, 0};
  p.doubles_aim = Eigen::Vector2d(0.6, 0);
  p.net_margin = 0.08;
  p.trunk_reach = 0.12;
  p.max_back = 0.35;
  p.follow = 0.1;
  p.max_speed = 4;
  p.horizon_s = 1.5;
  p.legs.balance = {0.5, 0.5, -0.2, 2.0};
  // The sidestep: the feed comes at the body line, 0.45 m left of the forehand's sweet spot, and
  // the legs have about 0.3 s to step there before they settle. Quicker, faster side steps
  // (0.25 s, up to 1 m/s; the walker's defaults 0.3 s, 0.55 m/s) meet more of them on the
  // forehand side: tuning seeds 1-10 / 11-30, strokes per point 0.93 -> 1.17 / 0.99 -> 1.16,
  // points without a stroke 40% -> 32% / 39% -> 32%, ball return (seeds 1-200) 33% -> 37%.
  p.legs.step_s = 0.25;
  p.legs.max_side_speed = 1.0;
  // The backswing drawn over the last 0.4 s before the swing (from about 0.65 s before contact,
  // as the legs settle), the face at the ready point until then: held drawn back from the
  // stroke's planning, the arm lay across the body's line while the legs stepped, and the player
  // fell. Tuning seeds 1-10 / 11-40: falls 0.91 -> 0.07 / 0.65 -> 0.23 a minute, strokes per
  // point 1.17 -> 1.19 / 1.17 -> 1.28 (docs/racket-sports.md).
  p.draw_s = 0.4;
  // Doubles: the partner whose ball it is not stands still at its mark (the marks are staggered,
  // so it is out of the striker's way). Tuning seeds 1-10, with the first-stroke rule (my_ball):
  // standing, no fall and 0.99 strokes per point; stepping back 0.3 m, 1.23 strokes per point but
  // 0.54 falls a minute (docs/racket-sports.md, doubles).
  p.doubles_step_back = 0;
  // Of the first doubles serves of tuning seeds 1-200 (with the planner's 0.3 rad): turned 3
  // degrees 111 in (88 out: on the receiver's left half), 5 degrees 182 in (18 lets, no fault), 7
  // degrees 168 in (docs/racket-sports.md, the doubles serve).
  p.doubles_serve_turn = 5 * M_PI / 180;
  // Doubles: the right-hand partner, its stroke next, waits on the centre line (its mark: y =
  // -0.4 m). Opponents aim at the centre line; the third ball (the partner's first stroke) came
  // down 0.3-0.6 m toward the partner and, met 0.25 m right of the root, needed the right-hand
  // player to walk 0.4-1 m in about 0.85 s: it played 20 of 131 (the left-hand one 82 of 133).
  // Tuning seeds 1-12: third ball played 27.5% -> 44.3% of the points reaching it, 4 or more
  // strokes 9 -> 22, falls 3 -> 2 (issue 29; docs/racket-sports.md, the third ball).
  p.doubles_next_right_y = 0.0;
  // The legs let go of balls they cannot get to: a ball swung at and missed is not chased along
  // its path behind the player, and a ball out of reach is walked to only while its stance is
  // within 0.6 m/s x the time left + 0.5 m. Of the 12 falls traced in 1v1 on tuning seeds 1-40,
  // 5 came chasing so (a missed ball re-planned, or a stance 0.9-2.2 m away with 0.1-0.4 s left,
  // the body lunging at 1-1.5 m/s). Ball return, tuning seeds 1-300: returns in 213 -> 211 of
  // about 512, falls 5 -> 1 (issue 29, ninth round; docs/racket-sports.md).
  p.let_go_missed = true;
  p.chase_slack = 0.5;
  // A point that ends while a player's stroke is committed (its ball on the body, say) left that
  // stroke running into the next point: committed, it counted down against the new feed, was
  // let go as missed, and the fed player planned nothing for the feed, which then struck its
  // body or passed it (1v1 tuning seeds 1-2: 6 of 35 feeds). Dropped at the new point (1v1
  // tuning seeds 1-8): points without a stroke 23.2% -> 15.7%, strokes per point 1.95 -> 2.03;
  // in doubles (2v2 tuning seeds 1-4) sides fed with neither partner planning 6 of 59 -> 4 of 71
  // (issue 29, short points; docs/racket-sports.md).
  p.forget_stroke_at_new_point = true;
  // The face asked for 4 cm left of the planned contact (issue 29, body touches): it came short,
  // to the right of the ball, which then ran on into the trunk. Only for balls met between the
  // shoulder's line and the root's (face_aim_bias): everywhere, 1v1 falls rose 5 -> 13 in about
  // 130 min. Unseen 1v1 seeds 198101-198180: strokes per point 1.83 -> 1.94, body touches per
  // point 0.436 -> 0.395, falls 10 -> 7 in about 127 min (docs/racket-sports.md).
  p.face_aim_bias = {0, 0.04, 0};
  // The backhand round (issue 29): balls met on or left of the root's line were almost never
  // struck (1v1 tuning seeds 1-4: 0 of 27). With either side of the paddle allowed, the inverse
  // kinematics turned the wrist over to the back face for them (a backhand grip); that posture
  // was solved exactly (error under 3 mm), but the arm driven toward it left the face a median
  // 15 cm right of and 16 cm below the ball, which ran on into the trunk. The front face, the arm
  // reaching across as on the forehand, follows its goal: 1v1 tuning seeds 1-20, strokes per
  // point 2.08 -> 3.00 (median 1 -> 3), points without a stroke 16.0% -> 6.4%, body touches per
  // point 0.379 -> 0.328, falls 2 -> 1. A backhand swing (the line turned 0.6 rad right, drawn
  // back from the left) with either face: seeds 1-4, 1.81 -> 1.53 (docs/racket-sports.md).
  p.front_face_only = true;
  // A new point starts the legs afresh (Play::FreshLegs), stepping at once, the
  // trailing foot first. Before, a step under way when the last point ended ran on at 97% of
  // point starts (1v1 tuning seeds 61-80), the swing foot yanked up mid-step from the feet the
  // match had just put back. Started afresh and standing, the body toppled forward (this
  // standing balance) at about 0.2 m/s until a catch step 0.45 s in, and the walk home (2 m
  // back -> 1.8) is under the walker's 0.3 m start distance; stepping at once by the lead foot,
  // the fed player sidestepped the feed's full 0.25 m and struck it still moving (points lost on
  // the feed's stroke, into the net, short or out: main 16%, 33%). The trailing foot first, it
  // meets the feed about where it stands: 5%; strokes a point 3.62 -> 4.22 (11 matches; issue
  // 29, the legs at a point's start; docs/racket-sports.md).
  p.fresh_legs.at_new_point = true;
  p.fresh_legs.step_at_once = true;
  p.fresh_legs.in_doubles = false;
  // Measured at fed points only. At tosses, stepping at once, a 1v1 with serves to 5 went point
  // for point to its 120 s limit (seed 1: 73 points, two servers in; ScriptedRacketServe).
  p.fresh_legs.at_tosses = false;
  return p;
}

Eigen::Vector3d face_aim_bias(const Play& play, const Eigen::Vector3d& met,
                              const Eigen::Vector3d& shoulder) {
  // A fed ball the face misses there runs on into the trunk (one met right of the shoulder passes
  // beside the body); past the root's line the arm already reaches across the body, and the bias
  // there drew it further across (the falls above).
  return met.y() > shoulder.y() && met.y() < 0 ? play.face_aim_bias : Eigen::Vector3d::Zero();
}

Play tennis_play() {
  Play p;
  p.sweet_spot = {0.55, -0.75, 0.25};
  p.above = 0.6;
  p.home_x = -11.885;
  p.aim = {7.5, 0};
  p.net_margin = 0.3;
  p.max_back = 0.4;
  p.follow = 0.2;
  p.max_speed = 8;
  p.horizon_s = 3.0;
  p.legs.balance = {1.0, 2.0, 0.0, 1.0};
  // The arc swing: measured on tuning seeds (1v1 feeds, 1-4), the face at the planned contact
  // moves at a median 3.6 m/s along the swing (the straight swing: 1.5 m/s), 0.55 m from the
  // planned point (0.57 m); the arm lags a swing driven at the planned rate by about a quarter,
  // hence the 1.3. Returns in stay within noise of the straight swing's (docs/racket-sports.md).
  p.max_back_angle = 1.2;
  p.arc_speeds = {2, 3, 4, 5, 6, 7, 8};
  p.arc_drive = 1.3;
  // In joint space, from rest (issue 29, fourth round; tuning seeds 1-300): balls touched 9 ->
  // 18 of about 300, returned in 0 -> 4; the face lagged its goal by about a tick at contact.
  p.joint_swing = true;
  p.swing_lead_s = 0.033;
  // The serve (issue 29, the tennis serve round): a ball into the box from the baseline leaves
  // the face at 12-15 m/s, which a level straight swing never gave (0 of 300 in). Swung on the
  // rally's joint-space arc at the planned 10-11 m/s (driven 1.3 times faster, as the rally's),
  // the face moved at 13-16 m/s, but the body spun 0.5-0.75 rad clockwise under the racket arm's
  // reaction before contact and the face came 15-20 cm low and inside: 4 of 200 first serves in
  // (tuning seeds 41-240). With the turn's inertial load held (drive_turned_arm) and the free arm
  // swung the other way (the spin about 0.2 rad), the balls were struck but went long and left
  // (planned 0.40 rad up, 0.31 left; delivered 0.4-0.8 up, 0.4-0.6 left): the normal tilted 0.2
  // down and turned 0.2 right, 18 of 200 in (docs/racket-sports.md, the tennis serve).
  p.serve_speeds = {6, 7, 8, 9, 10, 11, 12, 13, 14};
  p.serve_tilt_down = 0.2;
  p.serve_turn_right = 0.2;
  // The match's toss falls 0.6 m ahead and 0.75 m right of the server, about 0.85-0.9 m from its
  // shoulder: at the rally's 0.9 of the reach (0.85 m) no point of it was within reach for 18 of
  // 200 first serves (1v1, tuning seeds 41-240; 29 of 200 in 2v2): no serve was swung at all.
  // At 0.95 every toss is met (1v1 18 -> 24 of 200 in; 2v2 26 -> 31; issue 29, the serve's
  // second round, docs/racket-sports.md).
  p.serve_reach_fraction = 0.95;
  // Of the 20 falls on ball-return tuning seeds 1-400 without this, 15 came while the legs
  // walked to a ball out of reach; in 12 of those, and 3 more just after a swing, toward a
  // stance 3-9 m away (a ball that bounces twice before the legs get there, or one chased again
  // after it passed): the plain gait, asked for its top speed, ran away sideways or backward at
  // 1-2 m/s and the player fell (issue 29, tennis falls; docs/racket-sports.md).
  // Tuning seeds 1-400, falls 20 -> 11, returns in 5 -> 5, touched 26 -> 26; with 0.5 m of
  // slack 4 falls, but 2 returns in (balls the legs reach at 0.6 m/s only with about 1.1 m).
  p.chase_slack = 1.2;
  // A softer catch than the walker's default (velocity_gain 0.13: how much further the swing
  // foot lands per m/s the body moves off what is asked). Of the 11 falls left on ball-return
  // tuning seeds 1-400, most came in and after the swing, the legs stepping in place while the
  // body swayed 0.5-1 m/s, its sideways speed changing sign from step to step as the racket swung
  // across it (seeds 12, 309, 316, 364, 382), as if each step over-corrected the last. Tuning seeds
  // 1-400 (in / touched / falls): 0.13: 5 / 26 / 11; 0.10: 5 / 22 / 4; 0.08: 4 / 17 / 6;
  // 0.25: 5 / 23 / 56 (docs/racket-sports.md, tennis falls, second round).
  p.legs.velocity_gain = 0.10;
  // Of 15 falls traced in 1v1 on tuning seeds 1-6, every one was the fed player sidestepping to
  // the feed (it comes at the body; the legs put it at the sweet spot, about 1 m aside), the body
  // running sideways at a median 1.4 m/s and, in 12, forward at 0.7-2 m/s; meanwhile the arm, in
  // the joint-space swing from the first tick the ball was within reach, held the contact posture
  // solved where the body stood: reaching across the body's line for a ball still 1 m to the
  // left of where it is met, as the legs walked there. Readied from the stance instead: 1v1 tuning
  // seeds 1-8, falls 23 in 20.5 min -> 7 in 21.0 min, points with a stroke 22.6% -> 19.0% (issue
  // 29, tennis falls in 1v1, second round; docs/racket-sports.md).
  p.swing_once_settled = true;
  // At half the point starts the legs were still in a step from the point before, run on from
  // where the feet had been, while the match had put the body back standing at its mark (18 of
  // 36 in the first 10 points of 1v1 seeds 1-2; the body jolted: root speed on the point's first
  // tick, median 0.18 m/s, 0.08 afresh).
  // Of 11 falls traced in 1v1 on tuning seeds 1-8 and 17-24, 8 were a forward lunge (6 of them
  // the fed player's, 0.8-1.5 s into the point): the body surging forward, the right foot swung
  // 0.4-0.8 m ahead, a knee down. Legs started afresh, falls 11 in 39.5 min -> 7 in 43.1 min;
  // unseen seeds 210001-210016, 22 in 61.9 min -> 11 in 48.0 min (0.36 -> 0.23 a minute, z 1.2),
  // strokes per point 0.179 -> 0.196 (issue 29, tennis falls in 1v1, fifth round;
  // docs/racket-sports.md).
  p.fresh_legs.at_new_point = true;
  return p;
}

}  // namespace olympics::client::racket_play
