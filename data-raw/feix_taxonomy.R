# Builds data/feix_taxonomy.rda and data/hust_dofs.rda.
# Feix, T., Romero, J., Schmiedmayer, H.-B., Dollar, A. M. and Kragic, D. (2016).
# The GRASP taxonomy of human grasp types. IEEE Transactions on Human-Machine
# Systems 46(1), 66-77: the 33 types with their class (power / intermediate /
# precision), opposition type, virtual-finger assignment and thumb position.
# Names follow the thesis' Table 5.1 (Jeppsson 2017), which numbers the types 1-33.
# The columns follow the paper's Fig. 4 (the overview of the 33 types with class,
# opposition type, virtual fingers and thumb position). Checked against it (the
# first version was typed from memory): 18 Extension Type VF2 2-4 (not 2-5);
# 21 Tripod Variation intermediate (not precision); 26 Sphere 4 Finger and
# 28 Sphere 3 Finger pad opposition with VF1 the thumb (not palm); 32 Ventral
# VF2 2 (not 3).
# 23 Adduction Grip: VF1 2 (index), VF2 3 (middle), kept. The object is held
# between the sides of index and middle finger; the taxonomy lists one
# finger, 3, as the type's virtual finger, in the place every other type
# uses for VF2. Source of that reading: a third-party annotation tool built
# on the taxonomy (a MATLAB GUI found by code search) writes "3" in its VF2
# field for Adduction Grip, and agrees with Fig. 4 where we could check it
# (2-4 for Extension Type, intermediate 3-4 for Tripod Variation, pad for
# the two sphere types, 2 for Ventral); the paper's figure itself was not at
# hand. So the index is the opposing VF1. Swapping
# them would not change the simulated posture (both fingers take the `side`
# role); it decides only which finger's flexion follows the object size.
tax <- read.table(text = "
id|name|class|opposition|vf1|vf2|vf3|thumb
1|Large Diameter|power|palm|palm|2-5||abducted
2|Small Diameter|power|palm|palm|2-5||abducted
3|Medium Wrap|power|palm|palm|2-5||abducted
4|Adducted Thumb|power|palm|palm|2-5|1|adducted
5|Light Tool|power|palm|palm|2-5|1|adducted
6|Prismatic 4 Finger|precision|pad|1|2-5||abducted
7|Prismatic 3 Finger|precision|pad|1|2-4||abducted
8|Prismatic 2 Finger|precision|pad|1|2-3||abducted
9|Palmar Pinch|precision|pad|1|2||abducted
10|Power Disk|power|palm|palm|2-5||abducted
11|Power Sphere|power|palm|palm|2-5||abducted
12|Precision Disk|precision|pad|1|2-5||abducted
13|Precision Sphere|precision|pad|1|2-5||abducted
14|Tripod|precision|pad|1|2-3||abducted
15|Fixed Hook|power|palm|palm|2-5||adducted
16|Lateral|intermediate|side|1|2||adducted
17|Index Finger Extension|power|palm|palm|3-5|2|adducted
18|Extension Type|power|pad|1|2-4||abducted
19|Distal Type|power|pad|1|2-5||abducted
20|Writing Tripod|precision|side|1|3|2|abducted
21|Tripod Variation|intermediate|side|1|3-4|2|abducted
22|Parallel Extension|precision|pad|1|2-5||adducted
23|Adduction Grip|intermediate|side|2|3||abducted
24|Tip Pinch|precision|pad|1|2||abducted
25|Lateral Tripod|intermediate|side|1|3|2|adducted
26|Sphere 4 Finger|power|pad|1|2-4||abducted
27|Quadpod|precision|pad|1|2-4||abducted
28|Sphere 3 Finger|power|pad|1|2-3||abducted
29|Stick|intermediate|side|1|2||adducted
30|Palmar|power|palm|palm|2-5||adducted
31|Ring|power|pad|1|2||abducted
32|Ventral|intermediate|side|1|2||adducted
33|Inferior Pincer|precision|pad|1|2||abducted
", sep = "|", header = TRUE, stringsAsFactors = FALSE, strip.white = TRUE,
   colClasses = "character")
feix_taxonomy <- data.frame(
  id = as.integer(tax$id),
  name = tax$name,
  class = factor(tax$class, levels = c("power", "intermediate", "precision")),
  opposition = factor(tax$opposition, levels = c("palm", "pad", "side")),
  vf1 = tax$vf1, vf2 = tax$vf2, vf3 = ifelse(tax$vf3 == "", NA, tax$vf3),
  thumb = factor(tax$thumb, levels = c("abducted", "adducted")),
  stringsAsFactors = FALSE
)

# The 16 DoFs of the HUST data glove, in file column order (thesis Figure 4.1).
hust_dofs <- data.frame(
  index = 1:16,
  name = c("CMC1", "ABD1", "MCP1", "IP1", "MCP2", "PIP2", "DIP2", "MCP3", "PIP3",
           "DIP3", "MCP4", "PIP4", "DIP4", "MCP5", "PIP5", "DIP5"),
  finger = factor(c(rep("thumb", 4), rep("index", 3), rep("middle", 3),
                    rep("ring", 3), rep("little", 3)),
                  levels = c("thumb", "index", "middle", "ring", "little")),
  joint = c("CMC", "CMC", "MCP", "IP", rep(c("MCP", "PIP", "DIP"), 4)),
  motion = c("flexion", "abduction", rep("flexion", 14)),
  stringsAsFactors = FALSE
)

save(feix_taxonomy, file = "data/feix_taxonomy.rda", compress = "xz", version = 2)
save(hust_dofs, file = "data/hust_dofs.rda", compress = "xz", version = 2)
