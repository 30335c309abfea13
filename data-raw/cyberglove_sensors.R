# Builds data/cyberglove_sensors.rda: the 23 sensor columns of a GraspDB14
# motion file (Stollenwerk, Hinkenjann and Klein 2018, Tables 3.1, 4.3 and 5.1).
#   index      column among the 23 sensors (1-23); `key` is the field in the
#              30-field data row (Table 4.3: keys 8-30)
#   sensor_no  sensor number 0-22 (Tables 3.1 / 4.3, Figure 3.1b)
#   name       sensor denotation of Table 4.3
#   status     "measured" (present on the 18-sensor glove), "inferred" (marked *
#              in Table 4.3: no DIP sensor; zero in raw files, inferred in angle
#              files) or "unsupported" (marked **: always 0)
#   joint_skel, axis   skeleton joint and local rotation axis of Table 5.1
#              (axis NA where the report marks the sensor as discarded)
#   hust_dof   the HUST DoF (Jeppsson 2017, Figure 4.1) this sensor corresponds
#              to, NA where HUST has no such DoF (finger ab-/adduction,
#              palm arch, wrist)
#   hust_sign  factor applied (with rad -> deg) by graspdb14_to_hust(): the
#              GraspDB14 angle files store flexion as negative angles (the
#              MATLAB viewer animates -angledata); HUST stores flexion as
#              positive, so flexion sensors are negated. Thumb-index abduction
#              (TI-AA) grows as the thumb abducts, so it is kept.
# Run from the package root: Rscript data-raw/cyberglove_sensors.R
cyberglove_sensors <- read.table(text = "
index|sensor_no|key|name|finger|joint|motion|status|joint_skel|axis|hust_dof|hust_sign
1|0|8|T-TMJ|thumb|TMJ|rotation across palm|measured|th-tmc|z|CMC1|-1
2|1|9|T-MCPJ|thumb|MCP|flexion|measured|th-mcp|x|MCP1|-1
3|2|10|T-IPJ|thumb|IP|flexion|measured|th-ip|x|IP1|-1
4|3|11|TI-AA|thumb|TMJ|abduction|measured|th-mcp|z|ABD1|1
5|4|12|I-MCPJ|index|MCP|flexion|measured|if-mcp|x|MCP2|-1
6|5|13|I-PIPJ|index|PIP|flexion|measured|if-pip|x|PIP2|-1
7|6|14|I-DIPJ|index|DIP|flexion|inferred|if-dip|x|DIP2|-1
8|7|15|I-AA|index|MCP|abduction|unsupported|if-mcp|||
9|8|16|M-MCPJ|middle|MCP|flexion|measured|mf-mcp|x|MCP3|-1
10|9|17|M-PIPJ|middle|PIP|flexion|measured|mf-pip|x|PIP3|-1
11|10|18|M-DIPJ|middle|DIP|flexion|inferred|mf-dip|x|DIP3|-1
12|11|19|MI-AA|middle-index|MCP|abduction|measured|if-mcp|z||
13|12|20|R-MCPJ|ring|MCP|flexion|measured|rf-mcp|x|MCP4|-1
14|13|21|R-PIPJ|ring|PIP|flexion|measured|rf-pip|x|PIP4|-1
15|14|22|R-DIPJ|ring|DIP|flexion|inferred|rf-dip|x|DIP4|-1
16|15|23|RM-AA|ring-middle|MCP|abduction|measured|rf-mcp|z||
17|16|24|L-MCPJ|little|MCP|flexion|measured|lf-mcp|x|MCP5|-1
18|17|25|L-PIPJ|little|PIP|flexion|measured|lf-pip|x|PIP5|-1
19|18|26|L-DIPJ|little|DIP|flexion|inferred|lf-dip|x|DIP5|-1
20|19|27|LR-AA|little-ring|MCP|abduction|measured|lf-mcp|z||
21|20|28|P-Arch|palm|CMC|palm arch|measured|lf-cmc|||
22|21|29|W-FE|wrist|wrist|flexion|measured|root|x||
23|22|30|W-AA|wrist|wrist|abduction|measured|root|z||
", sep = "|", header = TRUE, stringsAsFactors = FALSE, na.strings = "", strip.white = TRUE)
for (v in c("index", "sensor_no", "key", "hust_sign")) cyberglove_sensors[[v]] <- as.integer(cyberglove_sensors[[v]])
stopifnot(nrow(cyberglove_sensors) == 23L, sum(cyberglove_sensors$status == "measured") == 18L,
          sum(!is.na(cyberglove_sensors$hust_dof)) == 16L)
save(cyberglove_sensors, file = "data/cyberglove_sensors.rda", compress = "xz", version = 2)
