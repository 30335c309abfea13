# Final hand postures of the 33 Feix grasp types for the simulator.
#
# A posture is derived in two steps, so that every number has a stated reason:
#   1. roles: each finger (2-5) and the thumb gets a role from the type's
#      taxonomy attributes in `feix_taxonomy` (opposition type, virtual-finger
#      assignment vf1/vf2/vf3, thumb abducted/adducted), and each role has a
#      typical MCP/PIP (fingers) or CMC1/ABD1/MCP1/IP1 (thumb) angle;
#   2. adjustments: a short per-type table of additions (degrees) for what the
#      attributes cannot say (object size of the type, hook vs wrap, straight
#      vs curled pads), each with a one-line note.
# DIP joints are not set here: the simulator drives them from the PIP angle
# (DIP about 2/3 of PIP), so postures cover the 12 "driven" DoFs only.
# Similar types get similar postures on purpose (the thesis could not tell
# prismatic 2/3/4 finger, precision disk/sphere/tripod, or adducted thumb/
# light tool/fixed hook apart), because they share roles and differ only by
# which fingers take part or by a small adjustment.

# The 12 DoFs whose angles the simulator drives directly; the 4 DIPs follow PIP.
sim_driven_dofs <- c("CMC1", "ABD1", "MCP1", "IP1", "MCP2", "PIP2", "MCP3", "PIP3",
                     "MCP4", "PIP4", "MCP5", "PIP5")
sim_dip_of_pip <- c(DIP2 = "PIP2", DIP3 = "PIP3", DIP4 = "PIP4", DIP5 = "PIP5")

# Finger (1 = thumb .. 5 = little) of each of the 16 HUST DoFs, by name.
sim_finger_of_dof <- function(dofs) {
  as.integer(ifelse(grepl("1$", dofs), 1L, sub("^[A-Z]+", "", dofs)))
}

# "2-5" -> 2:5, "1" -> 1, "palm"/NA/"" -> integer(0)
parse_virtual_finger <- function(x) {
  if (is.na(x) || !grepl("^[1-5](-[1-5])?$", x)) return(integer(0))
  ends <- as.integer(strsplit(x, "-", fixed = TRUE)[[1]])
  seq(ends[1], ends[length(ends)])
}

# Typical angles (degrees) of each role. Finger roles give c(MCP, PIP); thumb
# roles give c(CMC1, ABD1, MCP1, IP1). Flexion positive, ABD1 = abduction,
# CMC1 = thumb rotation towards opposition.
sim_default_roles <- function() {
  list(
    finger = rbind(
      wrap             = c(MCP = 55, PIP = 65), # VF2 of a palm (power) grasp: curls round the object
      pad              = c(MCP = 40, PIP = 30), # VF2 of a pad grasp: pads meet the thumb pad
      side             = c(MCP = 45, PIP = 55), # VF2 of a side grasp: object rests on the finger's side
      support          = c(MCP = 35, PIP = 30), # VF3 in a side grasp: index rests on top (writing)
      extended         = c(MCP = 5, PIP = 5),   # VF3 in a palm grasp: index pointing along a tool
      unused_power     = c(MCP = 60, PIP = 70), # not in contact, power class: tucked into the palm
      unused_precision = c(MCP = 45, PIP = 40)  # not in contact, otherwise: loosely curled
    ),
    thumb = rbind(
      pad_opposed  = c(CMC1 = 45, ABD1 = 45, MCP1 = 20, IP1 = 20), # VF1 pad, abducted: opposes finger pads
      pad_adducted = c(CMC1 = 30, ABD1 = 20, MCP1 = 15, IP1 = 10), # VF1 pad, adducted (parallel extension)
      side_opposed = c(CMC1 = 20, ABD1 = 15, MCP1 = 20, IP1 = 30), # VF1 side: thumb pad on a finger's side
      wrap         = c(CMC1 = 40, ABD1 = 50, MCP1 = 30, IP1 = 35), # palm grasp, abducted: closes round the object
      along        = c(CMC1 = 15, ABD1 = 10, MCP1 = 15, IP1 = 10), # VF3 in a palm grasp: lies along the handle
      adducted     = c(CMC1 = 10, ABD1 = 15, MCP1 = 15, IP1 = 15), # palm grasp, adducted, idle
      free         = c(CMC1 = 20, ABD1 = 30, MCP1 = 10, IP1 = 10)  # not part of the grasp (adduction grip)
    ),
    # MCP flexion grows towards the little finger (ulnar fingers sit lower).
    finger_mcp_offset = c(`2` = 0, `3` = 2, `4` = 4, `5` = 6)
  )
}

# Role of finger f (2-5) in taxonomy row `tx`.
sim_finger_role <- function(tx, f) {
  vf1 <- parse_virtual_finger(tx$vf1)
  vf2 <- parse_virtual_finger(tx$vf2)
  vf3 <- parse_virtual_finger(tx$vf3)
  opp <- as.character(tx$opposition)
  if (f %in% vf2) return(switch(opp, palm = "wrap", pad = "pad", side = "side"))
  if (f %in% vf1) return("side") # the index as VF1 (adduction grip)
  if (f %in% vf3) return(if (opp == "palm") "extended" else "support")
  if (tx$class == "power") "unused_power" else "unused_precision"
}

sim_thumb_role <- function(tx) {
  opp <- as.character(tx$opposition)
  abducted <- tx$thumb == "abducted"
  if (identical(tx$vf1, "1")) {
    if (opp == "side") return("side_opposed")
    return(if (abducted) "pad_opposed" else "pad_adducted")
  }
  if (identical(tx$vf1, "palm")) {
    if (1L %in% parse_virtual_finger(tx$vf3)) return("along")
    return(if (abducted) "wrap" else "adducted")
  }
  "free"
}

# Per-type adjustments (degrees added to the role angles). `fingers` uses the
# virtual-finger notation ("2-5", "1" = thumb), `joint` is MCP, PIP (fingers)
# or CMC1, ABD1, MCP1, IP1 (thumb).
sim_default_adjustments <- function() {
  a <- function(id, fingers, joint, delta) {
    data.frame(id = id, fingers = fingers, joint = joint, delta = delta, stringsAsFactors = FALSE)
  }
  rbind(
    a(1, "2-5", c("MCP", "PIP"), c(-20, -25)), a(1, "1", c("ABD1", "IP1"), c(10, -10)),
    a(2, "2-5", c("MCP", "PIP"), c(15, 20)), a(2, "1", c("MCP1", "IP1"), c(10, 10)),
    a(4, "2-5", c("MCP", "PIP"), c(5, 5)),
    a(5, "2-5", c("MCP", "PIP"), c(10, 5)), a(5, "1", "IP1", -5),
    a(6, "2-5", "PIP", -10), a(7, "2-4", "PIP", -10), a(8, "2-3", "PIP", -10),
    a(9, "2", "PIP", -5), a(9, "1", "CMC1", 5),
    a(10, "2-5", c("MCP", "PIP"), c(-15, -20)), a(10, "1", "ABD1", 15),
    a(11, "2-5", c("MCP", "PIP"), c(-10, -15)), a(11, "1", "ABD1", 10),
    a(12, "2-5", "MCP", -10), a(12, "1", "ABD1", 10),
    a(13, "2-5", "PIP", 5),
    a(14, "2-3", "PIP", 5),
    a(15, "2-5", c("MCP", "PIP"), c(-25, 10)),
    a(16, "2", "MCP", 5), a(16, "1", "IP1", -10),
    a(18, "2-4", c("MCP", "PIP"), c(-10, -20)), a(18, "1", "ABD1", 10),
    a(19, "2-5", "MCP", 5), a(19, "1", "CMC1", -10),
    a(22, "2-5", c("MCP", "PIP"), c(10, -25)),
    a(23, "2-3", c("MCP", "PIP"), c(-30, -40)),
    a(24, "2", "PIP", 25),
    a(25, "1", c("CMC1", "ABD1"), c(-5, -10)),
    a(26, "2-4", c("MCP", "PIP"), c(10, 20)),
    a(27, "2-4", "PIP", 5),
    a(28, "2-3", c("MCP", "PIP"), c(10, 20)),
    a(29, "2", "MCP", 10),
    a(30, "2-5", c("MCP", "PIP"), c(-30, -45)),
    a(31, "2", "PIP", 15),
    a(32, "2", "MCP", 5),
    a(33, "2", c("MCP", "PIP"), c(5, 10))
  )
}

# One line per type saying why its adjustment exists (or that it has none).
sim_adjustment_notes <- c(
  `1` = "large cylinder: wrapping fingers and thumb less flexed, thumb wide",
  `2` = "small cylinder: tight wrap, thumb closes over the fingers",
  `3` = "reference wrap round a medium cylinder (no adjustment)",
  `4` = "thumb lies along the handle (VF3); fingers wrap a medium handle",
  `5` = "thinner handle than adducted thumb: fingers flex a little more",
  `6` = "prismatic: straight fingers (little PIP flexion) pinch a thin object",
  `7` = "prismatic: straight fingers (little PIP flexion) pinch a thin object",
  `8` = "prismatic: straight fingers (little PIP flexion) pinch a thin object",
  `9` = "index pad meets thumb pad; thumb rotated a little further",
  `10` = "flat disk against the palm: fingers spread and less flexed, thumb wide",
  `11` = "sphere in the palm: fingers less flexed than a wrap, thumb wide",
  `12` = "fingertips on the rim of a disk: MCP less flexed, thumb wide",
  `13` = "fingertips round a small sphere: slightly more PIP flexion",
  `14` = "index and middle tips with the thumb: slightly more PIP flexion",
  `15` = "hook: PIPs strongly flexed with little MCP flexion, thumb idle",
  `16` = "thumb pad presses on the side of the curled index",
  `17` = "index extended along the tool (VF3), others wrap (no adjustment)",
  `18` = "flat object between the thumb and straight index-ring fingers (Feix VF2 2-4); the little finger, not in contact, curls (power class)",
  `19` = "fingers partly flexed and spread (scissors-like), thumb less rotated",
  `20` = "object on the middle finger's side, index on top (no adjustment)",
  `21` = "object on the side of middle and ring, index on top (no adjustment; intermediate class: a wider opening than writing tripod)",
  `22` = "fingers straight, flexed at the MCP only, pads against the thumb",
  `23` = "object clamped between the sides of index and middle: both nearly straight",
  `24` = "fingertip contact: index strongly flexed at PIP (and so DIP)",
  `25` = "as writing tripod, but the thumb is adducted: less rotated and abducted",
  `26` = "sphere held by thumb and index-ring pads (Feix: pad opposition, power class): fingers curve round it more than the pads of a precision grasp; little finger tucked",
  `27` = "four fingertips: slightly more PIP flexion",
  `28` = "sphere held by thumb, index and middle pads (Feix: pad opposition, power class): fingers curve round it more than the pads of a precision grasp; ring and little tucked",
  `29` = "stick between the thumb and the side of the index: index more flexed",
  `30` = "flat object pressed against the palm by nearly straight fingers",
  `31` = "thumb and index form a ring: index PIP more flexed",
  `32` = "object against the side of the index finger (Feix VF2 2), thumb adducted over it: index MCP a little more flexed",
  `33` = "index tip presses down on a small object: more flexed"
)

# Build the 33 x 12 matrix of final postures (rows = Feix ids 1-33, columns =
# the driven DoFs) and a data frame documenting each type's roles and note.
sim_build_postures <- function(roles = sim_default_roles(),
                               adjustments = sim_default_adjustments(),
                               taxonomy = handmotion::feix_taxonomy) {
  n <- nrow(taxonomy)
  post <- matrix(0, n, length(sim_driven_dofs),
                 dimnames = list(taxonomy$name, sim_driven_dofs))
  role_txt <- character(n)
  for (i in seq_len(n)) {
    tx <- taxonomy[i, ]
    th <- sim_thumb_role(tx)
    post[i, c("CMC1", "ABD1", "MCP1", "IP1")] <- roles$thumb[th, c("CMC1", "ABD1", "MCP1", "IP1")]
    fr <- character(4)
    for (f in 2:5) {
      fr[f - 1] <- sim_finger_role(tx, f)
      ang <- roles$finger[fr[f - 1], ]
      post[i, paste0("MCP", f)] <- ang[["MCP"]] + roles$finger_mcp_offset[[as.character(f)]]
      post[i, paste0("PIP", f)] <- ang[["PIP"]]
    }
    role_txt[i] <- sprintf("thumb %s; index %s, middle %s, ring %s, little %s",
                           th, fr[1], fr[2], fr[3], fr[4])
  }
  for (k in seq_len(nrow(adjustments))) {
    ad <- adjustments[k, ]
    fingers <- parse_virtual_finger(ad$fingers)
    cols <- if (identical(fingers, 1L)) ad$joint else paste0(ad$joint, fingers)
    post[ad$id, cols] <- post[ad$id, cols] + ad$delta
  }
  list(postures = post,
       notes = data.frame(id = taxonomy$id, name = taxonomy$name, roles = role_txt,
                          adjustment = unname(sim_adjustment_notes[as.character(taxonomy$id)]),
                          stringsAsFactors = FALSE))
}

# Which driven DoFs belong to the fingers that hold the object (VF2, or the
# thumb when it wraps round it); object size acts on these.
sim_build_object_mask <- function(taxonomy = handmotion::feix_taxonomy) {
  n <- nrow(taxonomy)
  mask <- matrix(0, n, length(sim_driven_dofs), dimnames = list(taxonomy$name, sim_driven_dofs))
  for (i in seq_len(n)) {
    tx <- taxonomy[i, ]
    for (f in parse_virtual_finger(tx$vf2)) {
      if (f == 1L) mask[i, c("MCP1", "IP1")] <- 1 else mask[i, paste0(c("MCP", "PIP"), f)] <- 1
    }
    if (sim_thumb_role(tx) %in% c("wrap", "pad_opposed")) mask[i, c("MCP1", "IP1")] <- 1
  }
  mask
}
