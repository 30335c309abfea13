# Builds data/graspdb14_objects.rda and data/graspdb14_actions.rda.
# Stollenwerk, Hinkenjann and Klein (2018), GraspDB14 technical report 01-2018:
# Table 4.1 (object id -> object name and the Feix grasp ids used on it in
# controlled transport) and Table 4.2 (action ids of scenario 2 -> action and
# leading hand). Run from the package root: Rscript data-raw/graspdb14-tables.R
graspdb14_objects <- read.table(text = "
id|name|grasp_ids
1|Tennis ball (64 mm diameter)|11, 13, 26, 27, 28, 33
2|Pen (2 cm diameter)|20
3|Bottle (8 cm diameter)|1
4|Mug|
5|Glass (62 mm diameter)|31
6|Bowl|
7|Cube|
8|Business card|9, 16
9|Oval jar|10
10|Bottle crate|3, 15
11|Classic notebook (15 mm thick)|18, 22, 30
12|Cylinder 10 mm diameter|6, 7, 8
13|Cylinder 25 mm diameter|2, 4, 17, 32
14|Carton lying flat|
15|Carton standing (7.6 x 26 x 37.5 cm^3)|
16|Bottle (cap)|14
", sep = "|", header = TRUE, stringsAsFactors = FALSE, na.strings = "", strip.white = TRUE)
graspdb14_objects$id <- as.integer(graspdb14_objects$id)
# objects with grasp ids were the ones used in controlled transport (scenario 3)
graspdb14_objects$controlled <- !is.na(graspdb14_objects$grasp_ids)

graspdb14_actions <- read.table(text = "
code|action_id|hand_id|action|hand
o_r|o|r|open|right
s_r|s|r|close|right
f_r|f|r|close tightly|right
i_r|i|r|interact|right
o_l|o|l|open|left
s_l|s|l|close|left
f_l|f|l|close tightly|left
", sep = "|", header = TRUE, stringsAsFactors = FALSE, strip.white = TRUE)

save(graspdb14_objects, file = "data/graspdb14_objects.rda", compress = "xz", version = 2)
save(graspdb14_actions, file = "data/graspdb14_actions.rda", compress = "xz", version = 2)
