-- scripts/paper/trends.lua with judge = means: each trend judged on the members' means by a
-- one-sided Welch t at 95 % (study_members.csv: the mirror image, the cuts through another
-- point). The fixture (trends_means.csv) has three members of each of the study's seven runs,
-- all at release 100, told apart by the point their cuts pass through (none, (1.22, 0.34),
-- (0.05, 3.07)); its numbers are made up so that each t below can be worked by hand. The bolted runs of a member share its mesh and cuts, so the bolts'
-- trends are paired member by member.
local here = debug.getinfo(1, "S").source:match("^@(.*[/\\])") or "./"
local check = dofile(here .. "trends_check.lua")
local expect, says = check.expect, check.says
local function verdicts(tables) return check.verdicts(tables, { judge = "means" }) end

local found, text = verdicts(here .. "trends_means.csv")
says(text, "3 runs of each case")
says(text, "100, 100 origin 0.05 3.07, 100 origin 1.22 0.34")
-- 310 +- 10 against 210 +- 10: t = 100 / sqrt(100/3 + 100/3) = 12.25 on 4 degrees of freedom (2.132).
expect(found, "Case 3 (denser joints) gives more new cracks than Case 2", "holds")
says(text, "cracks, Case 3 against Case 2: 310 ± 10 against 210 ± 10 (t 12.25, 3 members, 95 % needs 2.13)")
-- 212 m above 158 m by 5 (t 0.61, not resolved), 262 m below 212 m by 205: one comparison fails.
expect(found, "The crack count grows with depth, 158 < 212 < 262 m (Case 3)", "fails")
-- Paired: tension less shear 10, 12, 14 (t 10.39 on 2, needs 2.92); -6, 6, 2 (t 0.19); -50, -60, -40.
expect(found, "Tension cracks are the majority without bolts (Case 1)", "holds")
says(text, "tension less shear cracks: 12 ± 2 (t 10.39, 3 members, 95 % needs 2.92)")
expect(found, "Tension cracks are the majority without bolts (Case 2)", "not resolved")
expect(found, "Tension cracks are the majority without bolts (Case 3)", "fails")
-- 12 +- 2 m against 11 +- 1 m: t 0.77.
expect(found, "Case 2's cracks on the right side sit higher than Case 1's", "not resolved")
-- The bolted runs are paired with the unbolted run of the same member: 300, 310, 320 against
-- 295, 306, 314 cracks differ by 5, 4, 6 (t 8.66), where the means alone (310 against 305) would
-- not resolve it.
expect(found, "Pattern 1 lowers the crack count and the crown settlement (Case 3)", "holds")
says(text, "cracks, no bolts less pattern 1, member by member: 5 ± 1 (t 8.66, 3 members, 95 % needs 2.92)")
-- Pattern 2's count equals pattern 1's member by member: "at least as much" is tested as "more",
-- so not resolved although its crown settles less.
expect(found, "Pattern 2 lowers them at least as much as pattern 1 (Case 3)", "not resolved")
expect(found, "The side the joints dip towards (right) moves more (Case 1)", "holds")
-- Case 2's wall points fell 5 m behind the faces in one member and 15 m behind them in another.
expect(found, "The side the joints dip towards (right) moves more (Case 2)", "not shown")
-- Case 3's left point 5 m in fell in one member, so all three are read 15 m in: 0.10, 0.15, 0.20.
expect(found, "The side the joints dip towards (right) moves more (Case 3)", "holds")
says(text, "right less left wall, 15 m behind the faces [m]: 0.15 ± 0.05 (t 5.20, 3 members, 95 % needs 2.92)")
says(text, "5 of 11 trends hold.")

-- The seed's other statements, in a table of their own, judged the same way.
-- Case 1's right less left cracks 20, 22, 24: t = 22 / (2 / sqrt 3) = 19.05 on 2 (2.92).
expect(found, "Case 1's new cracks gather on the right side, towards which the joints dip (§4.1)", "holds")
says(text, "right less left cracks: 22 ± 2 (t 19.05, 3 members, 95 % needs 2.92)")
-- Right less left 10 m above the crown: no bolts 0.10, 0.11, 0.12 (t 19.05), pattern 1 0.01,
-- 0.02, 0.03 (t 3.46), pattern 2 -0.05, -0.06, -0.07 (t -10.39): one comparison fails.
expect(found, "Above the roof the right side comes down more than the left (Case 3; §4.2, Figure 12)", "fails")
says(text, "pattern 1, right less left half 10 m above the crown [m]: 0.02 ± 0.01 (t 3.46")
-- Blocks fallen, no bolts 20, 22, 27, less pattern 1's 10, 12, 14: 10, 10, 13 (t 11.00); less
-- pattern 2's 20, 22, 27: nothing (t 0): not resolved, although pattern 1 alone would hold.
expect(found, "Bolts hold the blocks around the opening: fewer fall with either pattern (Case 3; §4.2, Figure 11)",
       "not resolved")
says(text, "blocks fallen, no bolts less pattern 1, member by member: 11 ± 1.7 (t 11.00")
says(text, "1 of 3 other statements hold.")

-- One member of each run cannot be judged on means.
found, text = verdicts(here .. "trends_members_length.csv")
expect(found, "Case 3 (denser joints) gives more new cracks than Case 2", "not shown")
says(text, "needs two members of each run")

-- A run of Case 2 that stopped makes the trends that need Case 2 not shown, as with pairings.
found = verdicts(here .. "trends_means.csv," .. here .. "trends_members_stop.csv")
expect(found, "Case 3 (denser joints) gives more new cracks than Case 2", "not shown")

-- judge takes two words only.
local ok, err = pcall(check.verdicts, here .. "trends_means.csv", { judge = "mean" })
print(("%s: judge = mean refused (%s)"):format(ok and "WRONG" or "ok", tostring(err)))
if ok or not tostring(err):find("judge must be pairings or means, got mean", 1, true) then
  check.failures = check.failures + 1
end

if check.failures > 0 then error(("%d verdicts or texts not as expected"):format(check.failures), 0) end
print("trends judged on means: every verdict as expected")
