// Which edge a contact goes to: the squarest facing, the nearest among equals, and the edge it
// had kept while no other faces the gridpoint more than 10 degrees more squarely, or while the
// squarer one is an edge the gridpoint lies past the end of (beyond a corner, past both). The
// corner case is the seed cavern's: the tip of a 55 degree wedge pressed into the tip of the
// wedge across a crossing of two joints, whose two edges it faces equally.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/edge_choice.hpp"
#include "core/vec2.hpp"

namespace edem {
namespace {

Vec2 at_angle(double deg) { return {std::cos(deg * M_PI / 180.0), std::sin(deg * M_PI / 180.0)}; }

// The lower wedge's tip, pointing up: its edges' outward normals at 27.5 and 152.5 deg from +x.
// The upper wedge's two edges at its tip lie on their continuations across the crossing and
// face the other way, down-left (207.5 deg) and down-right (332.5 deg). Pressed into that tip,
// the gridpoint projects onto both (the tip is sharper than a right angle).
struct Tips {
  Vec2 own = at_angle(27.5) + at_angle(152.5);
  Vec2 down_left = at_angle(207.5), down_right = at_angle(332.5);
  double own_size() const { return norm(own); }
  double opposition(Vec2 edge_normal) const { return dot(edge_normal, own); }
};

TEST(EdgeChoice, TheSquarestFacingEdgeWinsWhateverTheDistance) {
  EdgeChoice choice{.own_size = 1.0};
  choice.offer(7, 0.001, -0.5, true);  // nearer, but 60 deg off
  choice.offer(8, 0.05, -1.0, true);   // squarely against it
  EXPECT_EQ(choice.chosen(), 8);
}

TEST(EdgeChoice, NothingOfferedNothingChosen) {
  const EdgeChoice choice{.held = 3, .own_size = 1.0};
  EXPECT_EQ(choice.chosen(), -1);
}

TEST(EdgeChoice, TipIntoTipWithNothingHeldTakesTheNearerEdge) {
  const Tips tips;
  ASSERT_NEAR(tips.opposition(tips.down_left), tips.opposition(tips.down_right), 1e-12);  // a tie
  EdgeChoice choice{.own_size = tips.own_size()};
  choice.offer(1, 0.020, tips.opposition(tips.down_left), true);
  choice.offer(2, 0.019, tips.opposition(tips.down_right), true);
  EXPECT_EQ(choice.chosen(), 2);
}

TEST(EdgeChoice, TipIntoTipKeepsItsEdgeAsTheOtherComesNearerOrTurnsALittleSquarer) {
  const Tips tips;
  // Held on the down-left face: the down-right one is nearer, and its block has turned 5 deg so
  // that it faces the tip more squarely; a choice afresh would swing the force by 120 deg.
  const Vec2 turned = at_angle(332.5 - 5.0);
  EdgeChoice fresh{.own_size = tips.own_size()}, held{.held = 1, .own_size = tips.own_size()};
  for (EdgeChoice* c : {&fresh, &held}) {
    c->offer(1, 0.020, tips.opposition(tips.down_left), true);
    c->offer(2, 0.019, tips.opposition(turned), true);
  }
  ASSERT_EQ(fresh.chosen(), 2);
  EXPECT_EQ(held.chosen(), 1);
}

TEST(EdgeChoice, AHeldEdgeGivesWayToOneFacingMoreThanTenDegreesSquarer) {
  // A gridpoint whose boundary faces straight up: its held edge has turned 25 deg away, the other
  // faces it squarely (a face sliding round a corner onto the next face).
  EdgeChoice choice{.held = 4, .own_size = 1.0};
  choice.offer(4, 0.01, -std::cos(25.0 * M_PI / 180.0), true);
  choice.offer(5, 0.01, -1.0, true);
  EXPECT_EQ(choice.chosen(), 5);
  // Turned only 9 deg: kept.
  EdgeChoice nine{.held = 4, .own_size = 1.0};
  nine.offer(4, 0.01, -std::cos(9.0 * M_PI / 180.0), true);
  nine.offer(5, 0.01, -1.0, true);
  EXPECT_EQ(nine.chosen(), 4);
}

TEST(EdgeChoice, AHeldEdgeTheGridpointHasSlidPastIsDropped) {
  // Sliding along a face made of edges in line: past the end of its edge, it goes on to the next,
  // which faces it as squarely and is as near.
  EdgeChoice choice{.held = 4, .own_size = 1.0};
  choice.offer(4, 0.011, -1.0, false);
  choice.offer(5, 0.010, -1.0, true);
  EXPECT_EQ(choice.chosen(), 5);
}

TEST(EdgeChoice, AHeldEdgeIsNotLeftForOneTheGridpointIsPastTheEndOf) {
  // A tip of one block past the corner of the other's face, over that block's side: the face
  // faces it 75 deg off squarely, the side 115 deg (it leans away), but the tip is past the face's
  // end. Held on the side, it stays there; with nothing held the squarer face wins.
  const double face = -std::cos(75.0 * M_PI / 180.0), side = -std::cos(115.0 * M_PI / 180.0);
  EdgeChoice held{.held = 2, .own_size = 1.0}, fresh{.own_size = 1.0};
  for (EdgeChoice* c : {&held, &fresh}) {
    c->offer(1, 0.24, face, false);
    c->offer(2, 0.21, side, true);
  }
  EXPECT_EQ(held.chosen(), 2);
  EXPECT_EQ(fresh.chosen(), 1);
}

TEST(EdgeChoice, BeyondACornerAPressedContactKeepsItsFaceWhicheverFacesSquarer) {
  // The matching gridpoint of a block's convex corner across a broken crack, just outside that
  // corner: past the ends of both edges that meet there, as near to each (the corner is the
  // nearest point of both), and facing them equally but for a hair that changes sign as the
  // blocks rock. Held on either while its contact presses, it stays; held open, or with nothing
  // held, the squarer one wins.
  const Vec2 own = 2.0 * at_angle(-19.5);  // facing both squarely as much
  const Vec2 pressed = at_angle(175.5), open = at_angle(145.5);  // 30 deg apart
  for (const double hair : {-1e-5, 1e-5}) {
    const double o_pressed = dot(pressed, own) + hair, o_open = dot(open, own) - hair;
    for (const int held : {1, 2}) {
      EdgeChoice choice{.held = held, .own_size = norm(own), .held_presses = true};
      choice.offer(1, 0.0006, o_pressed, false);
      choice.offer(2, 0.0006, o_open, false);
      EXPECT_EQ(choice.chosen(), held) << "hair " << hair;
      EdgeChoice opened{.held = held, .own_size = norm(own)};
      opened.offer(1, 0.0006, o_pressed, false);
      opened.offer(2, 0.0006, o_open, false);
      EXPECT_EQ(opened.chosen(), hair < 0.0 ? 1 : 2) << "hair " << hair;
    }
    EdgeChoice fresh{.own_size = norm(own)};
    fresh.offer(1, 0.0006, o_pressed, false);
    fresh.offer(2, 0.0006, o_open, false);
    EXPECT_EQ(fresh.chosen(), hair < 0.0 ? 1 : 2);
  }
}

TEST(EdgeChoice, AHeldEdgeNoLongerAmongTheNearOnesIsDropped) {
  EdgeChoice choice{.held = 4, .own_size = 1.0};
  // Edge 4 is not offered: further than the nearest by more than a tenth of the reach.
  choice.offer(5, 0.01, -0.9, true);
  EXPECT_EQ(choice.chosen(), 5);
}

}  // namespace
}  // namespace edem
