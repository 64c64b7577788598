# armmimic controller profile: the built-in defaults, written out.
#
# Copy this file, change what your controller does differently, and pass it with
#   armmimic-cli plan ANGLES.tsv -o PROGRAM.val --profile my.profile
#   armmimic-cli send PROGRAM.val --port /dev/ttyUSB0 --profile my.profile
# Format: one "key = value" per line; '#' starts a comment line; blank lines are ignored.
# Keys left out keep the defaults below. Unknown or repeated keys are errors (with the line).
# String values may use the escapes \r \n \t \\ (used for the terminator).
# The exact texts of a real VAL II controller's prompts and errors are not known for certain:
# these are the VAL/V+ manuals' conventions. See docs/robot.md.

# a label shown in messages
name = puma760-val2

# written after every line (\r = CR)
terminator = \r

# a received line exactly this: the monitor prompt
prompt_top = .

# a received line exactly this: prompt while a program runs
prompt_running = *

# a received line starting with this, then text: an error
error_prefix = *

# yes when the controller echoes what it receives
echo = yes

# longest line the controller accepts, without terminator
max_line_length = 80

# decimals written for joint angles
decimals = 2

# placeholders: {speed}
speed_template = SPEED {speed}

# stream mode move; placeholders {j1}..{j6}
move_template = DO MOVE #PPOINT({j1},{j2},{j3},{j4},{j5},{j6})

# program step move; placeholders {j1}..{j6}
program_move_template = MOVE #PPOINT({j1},{j2},{j3},{j4},{j5},{j6})

# placeholders {joint},{change},{speed}
drive_template = DO DRIVE {joint},{change},{speed}

# placeholder {name}
edit_template = EDIT {name}

# leaves the editor
end_edit_line = E

# placeholder {name}
execute_template = EXECUTE {name}

# stream (one DO MOVE per line) or program (EDIT ... E, then EXECUTE)
mode = stream

# program name in program mode
program_name = MIMIC

# seconds to wait for a prompt after a line
prompt_timeout_s = 5.000

# seconds to wait for a prompt after a motion line
motion_timeout_s = 60.000

# each joint's speed at SPEED 100, J1..J6, deg/s
joint_speed_at_100_deg_s = 60.0,60.0,60.0,120.0,120.0,120.0
