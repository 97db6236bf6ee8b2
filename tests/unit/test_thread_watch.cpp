// The thread watch's decisions, fed batch figures: a team whose threads wait for each other
// shrinks while the smaller team is not clearly slower, says so once, and grows back when a larger
// team is clearly faster again.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/thread_watch.hpp"

namespace edem {
namespace {

// One window's worth (0.1 s) of batches at `rate` cycles per second, each thread waiting `share`
// of the time.
TeamChange window(ThreadWatch& w, int team, double rate, double share, int wanted = 2) {
  TeamChange last;
  for (int batch = 0; batch < 20; ++batch) {
    const double wall = 0.00505;
    const TeamChange change = watch_team(w, team, wall, share * team * wall, std::lround(rate * wall), wanted);
    if (change.changed || !change.notice.empty()) last = change;
  }
  return last;
}

TEST(ThreadWatch, ABalancedTeamIsLeftAlone) {
  ThreadWatch w;
  for (int k = 0; k < 100; ++k) EXPECT_FALSE(window(w, 2, 4000, 0.2).changed);
  EXPECT_EQ(w.cap, 0);
}

TEST(ThreadWatch, ATeamThatWaitsForItsThreadsGoesOnWithOneAndSaysSoOnce) {
  ThreadWatch w;
  const TeamChange trial = window(w, 2, 1980, 0.6);  // 10 cycles a batch
  EXPECT_TRUE(trial.changed);
  EXPECT_EQ(w.cap, 1);
  const TeamChange kept = window(w, 1, 3762, 0.0);  // 19
  EXPECT_FALSE(kept.changed);
  EXPECT_NE(kept.notice.find("the 2 threads waited for each other 60 % of the time"), std::string::npos) << kept.notice;
  EXPECT_NE(kept.notice.find("goes on with 1 thread, at 1.9 times their speed"), std::string::npos) << kept.notice;
  EXPECT_EQ(w.cap, 1);
  // Ten seconds of cycling later two are tried again; still slower: one stays, and nothing is said.
  for (int k = 0; k < 99; ++k) EXPECT_FALSE(window(w, 1, 2800, 0.0).changed);
  EXPECT_TRUE(window(w, 1, 2800, 0.0).changed);
  EXPECT_EQ(w.cap, 0);
  const TeamChange back = window(w, 2, 1500, 0.6);
  EXPECT_TRUE(back.changed);
  EXPECT_TRUE(back.notice.empty());
  EXPECT_EQ(w.cap, 1);
}

TEST(ThreadWatch, TheFullTeamComesBackWhenTheOtherProcessEnds) {
  ThreadWatch w;
  window(w, 2, 1500, 0.6);
  window(w, 1, 2800, 0.0);
  for (int k = 0; k < 100; ++k) window(w, 1, 2800, 0.0);
  EXPECT_EQ(w.cap, 0);  // on trial
  EXPECT_FALSE(window(w, 2, 4000, 0.2).changed);
  EXPECT_EQ(w.cap, 0);
  for (int k = 0; k < 100; ++k) EXPECT_FALSE(window(w, 2, 4000, 0.2).changed);
}

TEST(ThreadWatch, ASmallerTeamClearlySlowerIsNotKeptAndNotTriedAgainAtOnce) {
  ThreadWatch w;
  EXPECT_TRUE(window(w, 2, 4000, 0.45).changed);  // waits much, but that is its imbalance
  EXPECT_EQ(w.cap, 1);
  const TeamChange back = window(w, 1, 2500, 0.0);
  EXPECT_TRUE(back.changed);
  EXPECT_TRUE(back.notice.empty());
  EXPECT_EQ(w.cap, 0);
  for (int k = 0; k < 99; ++k) EXPECT_FALSE(window(w, 2, 4000, 0.45).changed) << k;
  EXPECT_TRUE(window(w, 2, 4000, 0.45).changed);
}

TEST(ThreadWatch, FourThreadsOnThreeFreeCoresStepDownOneAtATime) {
  ThreadWatch w;
  window(w, 4, 1000, 0.6, 4);
  EXPECT_EQ(w.cap, 3);
  window(w, 3, 2900, 0.15, 4);
  EXPECT_EQ(w.cap, 3);
  for (int k = 0; k < 30; ++k) EXPECT_FALSE(window(w, 3, 2900, 0.15, 4).changed);
}

}  // namespace
}  // namespace edem
