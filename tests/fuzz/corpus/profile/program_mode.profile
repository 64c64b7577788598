# a controller without echo, in program mode
name = lab-puma
terminator = \r\n
echo = no
mode = program
program_name = ARM1
max_line_length = 72
decimals = 1
joint_speed_at_100_deg_s = 50,50,50,100,100,100
