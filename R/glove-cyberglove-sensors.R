# The 23 CyberGlove sensor columns of GraspDB14, the GraspDB14 object and
# action tables, and the mapping from GraspDB14 sensors to the 16 HUST DoFs.

#' The 23 CyberGlove sensors of GraspDB14 motion files
#'
#' One row per sensor column of a GraspDB14 motion file, in file order
#' (Stollenwerk et al. 2018, Tables 3.1, 4.3 and 5.1), with the HUST DoF each
#' one corresponds to (used by [graspdb14_to_hust()]).
#'
#' @format A data frame with 23 rows and 12 columns:
#' \describe{
#'   \item{index}{Column among the 23 sensors, 1-23.}
#'   \item{sensor_no}{Sensor number 0-22 of the report (Figure 3.1b).}
#'   \item{key}{Field of the sensor in the 30-field data row (8-30).}
#'   \item{name}{Sensor denotation of Table 4.3, e.g. `"T-TMJ"`, `"I-MCPJ"`,
#'     `"MI-AA"`; the DoF names of grasps read by [read_graspdb14()].}
#'   \item{finger}{thumb, index, middle, ring, little, the finger pair of an
#'     abduction sensor (e.g. `"middle-index"`), palm or wrist.}
#'   \item{joint}{TMJ, MCP, PIP, DIP, IP, CMC or wrist.}
#'   \item{motion}{flexion, abduction, rotation across palm or palm arch.}
#'   \item{status}{`"measured"` (the 18 sensors of the 18-sensor glove),
#'     `"inferred"` (the four DIP joints, marked * in Table 4.3: zero in raw
#'     files, estimated in angle files) or `"unsupported"` (I-AA, marked **:
#'     always 0).}
#'   \item{joint_skel}{Joint of the GraspDB14 default skeleton the sensor
#'     drives (Table 5.1).}
#'   \item{axis}{Local rotation axis of that joint (`x` flexion, `z`
#'     abduction); `NA` where the report discards the sensor (I-AA, P-Arch).}
#'   \item{hust_dof}{The HUST DoF ([hust_dofs]) the sensor corresponds to;
#'     `NA` for the sensors HUST has no DoF for (finger ab-/adduction, palm
#'     arch, wrist).}
#'   \item{hust_sign}{Sign applied when converting to HUST angles: -1 for
#'     flexion sensors (GraspDB14 angle files store flexion as negative
#'     angles), 1 for the thumb abduction TI-AA.}
#' }
#' @source Stollenwerk, K., Hinkenjann, A. and Klein, R. (2018). *GraspDB14 -
#'   Documentation on a database of grasp motions and its creation*. Technical
#'   report 01-2018, Hochschule Bonn-Rhein-Sieg. \doi{10.18418/978-3-96043-061-2}.
#'   Built by `data-raw/cyberglove_sensors.R`.
#' @seealso [graspdb14_to_hust()], [read_graspdb14()]
#' @examples
#' cyberglove_sensors[, c("name", "status", "hust_dof")]
"cyberglove_sensors"

#' GraspDB14 objects
#'
#' The objects of GraspDB14 and the Feix grasp types used on each in
#' controlled transport (Table 4.1 of the report).
#'
#' @format A data frame with 16 rows: `id` (object id of the file names),
#'   `name`, `grasp_ids` (Feix grasp ids, comma-separated, `NA` when the
#'   object was not used in controlled transport), `controlled` (logical).
#' @source Stollenwerk, Hinkenjann and Klein (2018), Table 4.1. Built by
#'   `data-raw/graspdb14-tables.R`.
#' @examples
#' graspdb14_objects[graspdb14_objects$controlled, c("id", "name", "grasp_ids")]
"graspdb14_objects"

#' GraspDB14 actions (scenario 2)
#'
#' The action ids of the object use and interaction scenario (Table 4.2 of the
#' report): `<obj>_<action>_<hand>_ex02-...` file names.
#'
#' @format A data frame with 7 rows: `code` (e.g. `"o_r"`), `action_id`,
#'   `hand_id`, `action` (open, close, close tightly, interact) and `hand`
#'   (leading hand, left or right).
#' @source Stollenwerk, Hinkenjann and Klein (2018), Table 4.2. Built by
#'   `data-raw/graspdb14-tables.R`.
#' @examples
#' graspdb14_actions
"graspdb14_actions"
