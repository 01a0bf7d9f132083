/*  oro full benchmark (issue #9): every figure of the issue in one run,
    each beside its floor.

        swipl bench/bench_full.pl [--sizes=10000,100000,1000000]
                                  [--samples=300] [--budget=15]
                                  [--json=bench/results.json]
                                  [--log=../shared/workloads/robot-session-2011.log]

    For each size, a server child process (server/oro_server.pl
    --port=0) loads a synthetic robot world of that many asserted
    triples over the socket, then one connection measures add 1, add a
    batch of 100, update, remove, check (asserted, inferred type,
    inferred property), find with 1 to 3 patterns, lookup, getInfos,
    the agents' findForAgent and addForAgent, 8 concurrent clients,
    and the latency of a NEW_INSTANCE event with 1,000 watchers
    registered.  Median, p99 and maximum of each, the server's memory
    (VmRSS after the load, VmHWM at the end).

    The floors, measured in the same run: an echo server with oro's
    framing and none of its work (bench_common:bench_echo_start/2, run
    as a child process of this script with --echo; re-measured before
    each size's figures, as the machine is noisy), raw rdf_assert/4 and
    rdf/3 in this process, and a bare `swipl -g halt` for the startup.
    Every figure is printed with its ratio to its floor.

    Then: startup to listening of the server with the bundled
    ontology; startup with the largest world written as Turtle and
    given with --ontology=FILE (and, as its floor, rdf_load/2 of the
    same file in this process); the replay of the robot session of
    2011 (all requests, each client thread on its own connection, in
    log order, no sleeps) on a fresh server with the robot id of that
    experiment; the 1M/100k ratios; the targets with PASS/MISS.

    A table on stdout, progress on stderr, and everything in the JSON
    file (default bench/results.json).  --budget bounds the seconds
    spent sampling one operation (at least 20 samples are taken).
*/

:- prolog_load_context(directory, Dir),
   asserta(user:file_search_path(oro_bench, Dir)).

:- use_module(library(semweb/rdf_db)).
:- use_module(library(semweb/turtle)).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(library(option)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(aggregate)).
:- use_module(library(pairs)).
:- use_module(library(http/json)).
:- use_module(library(main), [argv_options/3]).
:- use_module(bench_common).

%   main/0 runs only when this file is the script swipl was started with,
%   so that its predicates can be loaded and tried one by one.

:- prolog_load_context(file, File),
   (   current_prolog_flag(associated_file, File)
   ->  initialization(main, main)
   ;   true
   ).

opt_type(sizes, sizes, term).
opt_type(samples, samples, nonneg).
opt_type(budget, budget, nonneg).
opt_type(json, json, atom).
opt_type(log, log, atom).
opt_type(echo, echo, boolean).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    (   option(echo(true), Options)
    ->  echo_main
    ;   bench(Options)
    ).

%   echo_main: the echo server as a child process: print its port, then
%   serve until killed.

echo_main :-
    bench_echo_start(0, Echo),
    format("echo listening on 127.0.0.1:~w~n", [Echo.port]),
    flush_output,
    thread_get_message(_).

		 /*******************************
		 *            THE RUN           *
		 *******************************/

bench(Options) :-
    bench_list_option(sizes(Sizes), Options, [10000, 100000, 1000000]),
    option(samples(Samples), Options, 300),
    option(budget(Budget), Options, 15),
    absolute_file_name(oro_bench('results.json'), DefaultJSON),
    option(json(JSON), Options, DefaultJSON),
    absolute_file_name(oro_bench('../../shared/workloads/robot-session-2011.log'),
                       DefaultLog),
    option(log(Log), Options, DefaultLog),
    get_time(Start),
    nb_setval(bench_start, Start),
    bench_machine,
    machine(Machine),
    format("~d cores; ~w; sizes ~w, ~d samples, budget ~d s an operation~n",
           [Machine.cores, Machine.date, Sizes, Samples, Budget]),
    Params = params{samples:Samples, budget:Budget},
    in_process_floors(Floors),
    self_script(Self),
    bench_with_script(Self, ['--echo'], EchoPort, _,
                      maplist(size_figures(EchoPort, Params, Floors), Sizes, PerSize)),
    startup_figures(Startup),
    max_list(Sizes, Largest),
    turtle_figures(Largest, Turtle),
    replay_figures(Log, Replay),
    scaling(PerSize, Scaling),
    targets(PerSize, Startup, Turtle, Replay, Scaling, Targets),
    get_time(End),
    Total is End - Start,
    format("~nWhole run: ~1f s~n", [Total]),
    Results = results{machine:Machine, params:Params.put(sizes, Sizes),
                      floors:Floors, sizes:PerSize, startup:Startup,
                      turtle:Turtle, replay:Replay, scaling:Scaling,
                      targets:Targets, seconds:Total},
    write_json(JSON, Results),
    format("JSON: ~w~n", [JSON]).

self_script(File) :-
    absolute_file_name(oro_bench('bench_full.pl'), File, [access(read)]).

machine(machine{prolog:V, cpu:CPU, cores:Cores, date:Date}) :-
    current_prolog_flag(version, V),
    catch(( read_file_to_string('/proc/cpuinfo', Info, []),
            sub_string(Info, B, _, _, "model name"),
            sub_string(Info, B, 80, _, L0),
            split_string(L0, "\n", "", [Line|_]),
            split_string(Line, ":", " \t", [_, CPU])
          ), _, CPU = "unknown cpu"),
    current_prolog_flag(cpu_count, Cores),
    get_time(Now),
    format_time(string(Date), '%F %T', Now).

%   progress(+Format, +Args): a line on stderr, with the seconds since
%   the start.

progress(Format, Args) :-
    nb_getval(bench_start, Start),
    get_time(Now),
    T is Now - Start,
    format(user_error, "[~1f s] ", [T]),
    format(user_error, Format, Args),
    nl(user_error).

		 /*******************************
		 *       IN-PROCESS FLOORS      *
		 *******************************/

%   in_process_floors(-Floors): rdf_assert/4 of 100,000 triples shaped
%   like the world's into an empty graph (default hash tables, as the
%   server has), and bound rdf/3 probes on them.

in_process_floors(floors{rdf_assert_per_s:AssertRate, rdf_probe_per_s:ProbeRate,
                         triples:N}) :-
    progress("floors in process: rdf_assert/4, rdf/3", []),
    N = 100000,
    Graph = bench_floor,
    P = 'http://kb.openrobots.org#isOn',
    findall(rdf(S, P, O),
            ( between(1, N, I),
              format(atom(S), 'http://kb.openrobots.org#floor_obj~d', [I]),
              F is I mod 5000,
              format(atom(O), 'http://kb.openrobots.org#floor_f~d', [F])
            ), Triples),
    get_time(T0),
    forall(member(rdf(S, P, O), Triples), rdf_assert(S, P, O, Graph)),
    get_time(T1),
    forall(member(rdf(S, P, O), Triples), rdf(S, P, O)),
    get_time(T2),
    rdf_unload_graph(Graph),
    AssertRate is N / (T1 - T0),
    ProbeRate is N / (T2 - T1),
    format("~nFloors in this process (~D triples): rdf_assert/4 ~0f/s, \c
            bound rdf/3 ~0f/s~n", [N, AssertRate, ProbeRate]).

		 /*******************************
		 *          ONE SIZE            *
		 *******************************/

%   size_figures(+EchoPort, +Params, +Size, -Figures): everything
%   measured on a server holding a world of Size asserted triples.

size_figures(EchoPort, Params, Floors, Size, Figures) :-
    world(Size, World),
    progress("size ~D: starting a server", [Size]),
    bench_with_server([], Port, Pid,
                      bench_with_connection(
                          Port, C,
                          server_figures(C, Port, Pid, EchoPort, Params,
                                         Floors, World, Figures))).

server_figures(C, Port, Pid, EchoPort, Params, Floors, World, Figures) :-
    Size = World.size,
    load_world(C, World, Load),
    bench_memory(Pid, Loaded),
    progress("size ~D: loaded ~D statements, RSS ~w kB", [Size, Load.statements, Loaded.rss_kb]),
    echo_floors(EchoPort, Params, World, Echo),
    operations(C, Params, World, Echo, Ops),
    concurrency(Port, EchoPort, Params, World, Concurrent),
    event_figures(C, Params, World, Events),
    bench_memory(Pid, End),
    Figures = size{triples:Size, world:World.put(statements, Load.statements),
                   load:Load, memory_loaded:Loaded, memory_end:End,
                   echo:Echo, operations:Ops, concurrent:Concurrent,
                   events:Events, rdf_assert_per_s:Floors.rdf_assert_per_s},
    print_size(Figures).

		 /*******************************
		 *          THE WORLD           *
		 *******************************/

%   world(+Size, -World): the parameters of a synthetic robot world of
%   about Size asserted triples.
%
%     - Objects objI, typed under the common-sense classes (Cup, Plate,
%       Bottle, Book, Box, Toy, VideoTape, Spoon, Knife, AudioTape: all
%       Artifacts, most Tableware); 4 triples each: the type, where it
%       is (`isOn furnitureF`, or for one in five `isIn` a box, itself
%       an object), hasColor, isVisible.
%     - Furniture furnitureF, one for 20 objects (about 16 objects on
%       each whatever the size, so a find's answer does not grow with
%       the world), typed (Table, Shelf, Cupboard, Chair, Sofa,
%       ArmChair), labelled (`"table 12"`) and `isIn roomR`, ten to a
%       room; rooms are typed (Kitchen, LivingRoom, Bedroom) and
%       labelled.
%     - 10 agents humanA (Human, so the server gives each a model of
%       its own) that the robot sees looking at objects; 2% of the
%       triples are their beliefs, added to their models with
%       addForAgent: where objects are (often not where the robot put
%       them) and whether they are visible.

world(Size, world{size:Size, objects:Objects, furniture:NF, rooms:NR,
                  agents:NA, beliefs:Beliefs}) :-
    NA = 10,
    Beliefs is Size // 50,
    Objects is max(100, round((Size - Beliefs) / 4.16)),
    NF is max(1, Objects // 20),
    NR is (NF + 9) // 10.

%   room_of(+F, -R): furniture F is in room R, ten to a room.

room_of(F, R) :-
    R is 1 + (F - 1) // 10.

%   unit_statements(+World, +I, -Statements): object I's statements,
%   with those of the furniture and room introduced with it.

unit_statements(W, I, Statements) :-
    object_statements(W, I, Objs),
    (   I mod 20 =:= 0,
        F is I // 20,
        F =< W.furniture
    ->  furniture_statements(F, Furn),
        (   F mod 10 =:= 1
        ->  room_of(F, R),
            room_statements(R, Room)
        ;   Room = []
        )
    ;   Furn = [],
        Room = []
    ),
    (   I =< W.agents
    ->  agent_statements(W, I, Agent)
    ;   Agent = []
    ),
    append([Agent, Objs, Furn, Room], Statements).

object_statements(W, I, [Type, Place, Color, Visible]) :-
    object_class(I, Class),
    format(string(Type), "obj~d rdf:type ~w", [I, Class]),
    placement(W, I, Where, Target),
    format(string(Place), "obj~d ~w ~w", [I, Where, Target]),
    color(I, C),
    format(string(Color), "obj~d hasColor ~w", [I, C]),
    visible(I, V),
    format(string(Visible), "obj~d isVisible ~w", [I, V]).

object_class(I, Class) :-
    K is I mod 10,
    nth0(K, ['Cup', 'Plate', 'Bottle', 'Book', 'Box', 'Toy', 'VideoTape',
             'Spoon', 'Knife', 'AudioTape'], Class).

%   placement(+World, +I, -Property, -Target): where object I is.  One
%   object in five is in a box (an object whose index is 4 mod 10), the
%   others are on a piece of furniture.

placement(W, I, Property, Target) :-
    (   I mod 5 =:= 0
    ->  Property = isIn,
        Boxes is max(1, W.objects // 10),
        K is 10 * (((I // 5) * 7) mod Boxes) + 4,
        format(atom(Target), 'obj~d', [K])
    ;   Property = isOn,
        furniture_of(W, I, F),
        format(atom(Target), 'furniture~d', [F])
    ).

furniture_of(W, I, F) :-
    F is 1 + (I * 31) mod W.furniture.

color(I, C) :-
    K is (I // 10) mod 6,
    nth0(K, [red, green, blue, yellow, black, white], C).

visible(I, V) :-
    (   I mod 3 =:= 0
    ->  V = false
    ;   V = true
    ).

furniture_statements(F, [Type, Room, Label]) :-
    K is F mod 6,
    nth0(K, ['Table', 'Shelf', 'Cupboard', 'Chair', 'Sofa', 'ArmChair'], Class),
    format(string(Type), "furniture~d rdf:type ~w", [F, Class]),
    room_of(F, R),
    format(string(Room), "furniture~d isIn room~d", [F, R]),
    downcase_atom(Class, Name),
    format(string(Label), "furniture~d rdfs:label \"~w ~d\"", [F, Name, F]).

room_statements(R, [Type, Label]) :-
    K is R mod 3,
    nth0(K, ['Kitchen', 'LivingRoom', 'Bedroom'], Class),
    format(string(Type), "room~d rdf:type ~w", [R, Class]),
    downcase_atom(Class, Name),
    format(string(Label), "room~d rdfs:label \"~w ~d\"", [R, Name, R]).

agent_statements(W, A, [Type, Looks]) :-
    format(string(Type), "human~d rdf:type Human", [A]),
    X is 1 + (A * 97) mod W.objects,
    format(string(Looks), "human~d looksAt obj~d", [A, X]).

%   The beliefs of agent A: Beliefs/Agents statements about objects,
%   alternately where the object is (another piece of furniture than
%   the robot's) and that it is not visible.

belief_statements(W, A, Statements) :-
    N is W.beliefs // W.agents,
    findall(S, ( between(1, N, K),
                 belief(W, A, K, S)
               ), Statements).

belief(W, A, K, S) :-
    belief_object(W, A, K, I),
    (   K mod 2 =:= 0
    ->  G is 1 + (I * 17) mod W.furniture,
        format(string(S), "obj~d isOn furniture~d", [I, G])
    ;   format(string(S), "obj~d isVisible false", [I])
    ).

belief_object(W, A, K, I) :-
    I is 1 + (K * W.agents + A) mod W.objects.

		 /*******************************
		 *          LOADING             *
		 *******************************/

%   load_world(+Conn, +World, -Load): add the robot's world in batches
%   of 100 (timing each request), wait for the agents' models, add the
%   agents' beliefs with addForAgent in batches of 100.

load_world(C, W, load{statements:N, seconds:Seconds, per_s:Rate, batch:Batch,
                      robot_statements:NRobot, robot_per_s:RobotRate,
                      belief_statements:NBeliefs, belief_per_s:BeliefRate}) :-
    progress("size ~D: loading ~D objects", [W.size, W.objects]),
    load_robot(C, W, 1, [], RobotTimes0),
    append(RobotTimes0, RobotTimes),
    pairs_keys_values(RobotTimes, RobotCounts, RobotMicros),
    sum_list(RobotCounts, NRobot),
    sum_list(RobotMicros, RobotSum),
    wait_agents(C, W.agents, 60),
    numlist(1, W.agents, Agents),
    maplist(load_beliefs(C, W), Agents, BeliefTimes0),
    append(BeliefTimes0, BeliefTimes),
    pairs_keys_values(BeliefTimes, BeliefCounts, BeliefMicros),
    sum_list(BeliefCounts, NBeliefs),
    sum_list(BeliefMicros, BeliefSum),
    N is NRobot + NBeliefs,
    Seconds is (RobotSum + BeliefSum) / 1.0e6,
    Rate is N / max(1.0e-6, Seconds),
    RobotRate is NRobot / max(1.0e-6, RobotSum / 1.0e6),
    BeliefRate is NBeliefs / max(1.0e-6, BeliefSum / 1.0e6),
    include(full_batch, RobotTimes, Full),
    pairs_values(Full, FullMicros),
    bench_stats(FullMicros, Batch).

full_batch(100-_).

%   load_robot(+Conn, +World, +From, +Acc, -Times): the objects from
%   From on, 2,500 at a time (the statements are made a block at a
%   time, outside the timed requests).  Times are Count-Micros of each
%   request, a list a block, in reverse order.

load_robot(C, W, From, Acc, Times) :-
    (   From > W.objects
    ->  Times = Acc
    ;   To is min(W.objects, From + 2499),
        findall(S, ( between(From, To, I),
                     unit_statements(W, I, Ss),
                     member(S, Ss)
                   ), Statements),
        bench_batches(Statements, 100, Batches),
        load_batches(C, Batches, BlockTimes),
        (   (To // 2500) mod 40 =:= 0
        ->  progress("size ~D: ~D objects of ~D", [W.size, To, W.objects])
        ;   true
        ),
        Next is To + 1,
        load_robot(C, W, Next, [BlockTimes|Acc], Times)
    ).

load_batches(C, Batches, Times) :-
    maplist(load_batch(C), Batches, Times).

load_batch(C, Batch, Count-Micros) :-
    length(Batch, Count),
    bench_time(bench_call(C, add, [Batch]), Micros).

load_beliefs(C, W, A, Times) :-
    belief_statements(W, A, Statements),
    bench_batches(Statements, 100, Batches),
    format(atom(Agent), 'human~d', [A]),
    maplist(load_belief_batch(C, Agent), Batches, Times).

load_belief_batch(C, Agent, Batch, Count-Micros) :-
    length(Batch, Count),
    bench_time(bench_call(C, addForAgent, [Agent, Batch]), Micros).

%   wait_agents(+Conn, +N, +Seconds): poll listAgents until it lists
%   human1 ... humanN (their models are created after the add that
%   typed them has been answered).

wait_agents(C, N, Seconds) :-
    numlist(1, N, Is),
    maplist([I, A]>>format(atom(A), 'human~d', [I]), Is, Names),
    wait_listed(C, Names, Seconds).

wait_listed(C, Names, Seconds) :-
    get_time(Now),
    Deadline is Now + Seconds,
    wait_listed_(C, Names, Deadline).

wait_listed_(C, Names, Deadline) :-
    call_ok(C, listAgents, [], Value),
    atom_string(Text, Value),
    atom_json_term(Text, Listed0, [value_string_as(atom)]),
    (   subtract(Names, Listed0, [])
    ->  true
    ;   get_time(Now),
        Now < Deadline
    ->  sleep(0.01),
        wait_listed_(C, Names, Deadline)
    ;   throw(bench_failed(listAgents, timeout(Names, Listed0)))
    ).

%   call_ok(+Conn, +Method, +Params[, -Value]): a request whose reply
%   must be ok, within two minutes.

call_ok(C, Method, Params) :-
    bench_call(C, Method, Params, _, 120).

call_ok(C, Method, Params, Value) :-
    bench_call(C, Method, Params, Value0, 120),
    Value = Value0.

%   expect(+Conn, +Method, +Params, +Check): a request whose reply must
%   be ok with a value satisfying Check: `true`, `nonempty` (a JSON
%   list that is not empty), `list` (a JSON list) or `any`.  A wrong
%   answer stops the run: a fast wrong server is no result.

expect(C, Method, Params, Check) :-
    call_ok(C, Method, Params, Value),
    (   expected(Check, Value)
    ->  true
    ;   throw(bench_wrong_answer(Method, Params, Value))
    ).

expected(any, _).
expected(true, "true").
expected(list, Value) :-
    sub_string(Value, 0, 1, _, "[").
expected(nonempty, Value) :-
    sub_string(Value, 0, 1, _, "["),
    Value \== "[]".

		 /*******************************
		 *         ECHO FLOORS          *
		 *******************************/

%   echo_floors(+EchoPort, +Params, +World, -Echo): the echo server's
%   round trip for a one-statement request and a 100-statement one,
%   right before a size's figures.

echo_floors(EchoPort, Params, W, echo{one:One, batch:Batch}) :-
    bench_with_connection(
        EchoPort, E,
        ( bench_measure(Params.samples, Params.budget, I,
                        bench_call(E, check, [[S]], "true"),
                        asserted_statement(W, I, S), T1),
          bench_measure(Params.samples, Params.budget, I,
                        bench_call(E, add, [B]),
                        bulk_batch(W, I, B), T100)
        )),
    bench_stats(T1, One),
    bench_stats(T100, Batch).

		 /*******************************
		 *          OPERATIONS          *
		 *******************************/

%   operations(+Conn, +Params, +World, +Echo, -Ops): each operation of
%   op/8, in order, sampled with bench_measure/6; the first 5 samples
%   (first use of an index, first compilation of a schema closure) are
%   left out.

operations(C, Params, W, Echo, Ops) :-
    findall(Key, op(Key, _, _, C, W, _, _, _), Keys),
    maplist(operation(C, Params, W, Echo), Keys, Ops).

operation(C, Params, W, Echo, Key, Op) :-
    once(op(Key, Label, FloorKey, C, W, I, Goal, Prepare)),
    progress("size ~D: ~w", [W.size, Label]),
    N is Params.samples + 5,                % the first 5 warm up
    bench_measure(N, Params.budget, I, Goal, Prepare, Times0),
    warmed_up(Times0, Times),
    bench_stats(Times, Stats),
    Floor = Echo.FloorKey,
    Ratio is Stats.median / Floor.median,
    (   FloorKey == batch
    ->  PerSecond is 100 * 1.0e6 / Stats.median
    ;   PerSecond is 1.0e6 / Stats.median
    ),
    Op = op{key:Key, label:Label, stats:Stats, floor:FloorKey,
            floor_median:Floor.median, ratio:Ratio, per_s:PerSecond}.

warmed_up(Times0, Times) :-
    (   length(Warm, 5),
        append(Warm, Times, Times0),
        Times \== []
    ->  true
    ;   Times = Times0
    ).

%   op(?Key, ?Label, ?Floor, +Conn, +World, ?I, -Goal, -Prepare): an
%   operation measured over the socket: sample I runs Prepare, then
%   times Goal.  Floor is the echo figure it is compared with (`one`
%   for a request of one statement, `batch` for 100).  The order
%   matters: remove takes away what add 1 added.

op(add_1, "add 1 statement", one, C, W, I,
   call_ok(C, add, [[S]]),
   extra_statement(W, I, S)).
op(add_100, "add a batch of 100", batch, C, W, I,
   call_ok(C, add, [B]),
   bulk_batch(W, I, B)).
op(update, "update 1 (functional property)", one, C, W, I,
   call_ok(C, update, [[S]]),
   update_statement(W, I, S)).
op(remove, "remove 1 statement", one, C, W, I,
   call_ok(C, remove, [[S]]),
   extra_statement(W, I, S)).
op(check_asserted, "check, asserted", one, C, W, I,
   expect(C, check, [[S]], true),
   asserted_statement(W, I, S)).
op(check_type, "check, inferred type", one, C, W, I,
   expect(C, check, [[S]], true),
   ( sample_object(W, I, J),
     format(string(S), "obj~d rdf:type Artifact", [J])
   )).
op(check_property, "check, inferred property (isAt)", one, C, W, I,
   expect(C, check, [[S]], true),
   ( sample_object(W, I, J),
     placement(W, J, _, Target),
     format(string(S), "obj~d isAt ~w", [J, Target])
   )).
op(find_1, "find, 1 pattern (inferred property)", one, C, W, I,
   expect(C, find, ["o", [P]], nonempty),
   ( sample_furniture(W, I, F),
     format(string(P), "?o isAt furniture~d", [F])
   )).
op(find_2, "find, 2 patterns (+ inferred type)", one, C, W, I,
   expect(C, find, ["o", [P, "?o rdf:type Tableware"]], list),
   ( sample_furniture(W, I, F),
     format(string(P), "?o isAt furniture~d", [F])
   )).
op(find_3, "find, 3 patterns (room, furniture, type)", one, C, W, I,
   expect(C, find, ["o", ["?o isAt ?f", P, "?o rdf:type Tableware"]], list),
   ( R is 1 + I mod W.rooms,
     format(string(P), "?f isIn room~d", [R])
   )).
op(lookup_label, "lookup, a label", one, C, W, I,
   expect(C, lookup, [T], nonempty),
   ( Tables is max(1, W.furniture // 6),
     F is 6 * (1 + I mod Tables),
     format(string(T), "\"table ~d\"", [F])
   )).
op(lookup_name, "lookup, a name", one, C, W, I,
   expect(C, lookup, [T], nonempty),
   ( sample_object(W, I, J),
     format(string(T), "obj~d", [J])
   )).
op(get_infos, "getInfos", one, C, W, I,
   expect(C, getInfos, [T], nonempty),
   ( sample_object(W, I, J),
     format(string(T), "obj~d", [J])
   )).
op(find_for_agent, "findForAgent, 1 pattern (inferred)", one, C, W, I,
   expect(C, findForAgent, [Agent, "x", [P]], nonempty),
   ( A is 1 + I mod W.agents,
     format(atom(Agent), 'human~d', [A]),
     K is 2 * (1 + I mod max(1, W.beliefs // W.agents // 2)),
     belief_object(W, A, K, J),
     format(string(P), "obj~d isAt ?x", [J])
   )).
op(add_for_agent, "addForAgent 1 statement", one, C, W, I,
   call_ok(C, addForAgent, [Agent, [S]]),
   ( A is 1 + I mod W.agents,
     format(atom(Agent), 'human~d', [A]),
     furniture_of(W, I, F),
     format(string(S), "belief~d isOn furniture~d", [I, F])
   )).

%   The samples' statements.

extra_statement(W, I, S) :-
    furniture_of(W, I, F),
    format(string(S), "extra~d isOn furniture~d", [I, F]).

bulk_batch(W, I, Batch) :-
    findall(S, ( between(1, 100, K),
                 furniture_of(W, K, F),
                 format(string(S), "bulk~d_~d isOn furniture~d", [I, K, F])
               ), Batch).

%   sample_object(+World, +I, -J): the object of sample I, spread over
%   the world.

sample_object(W, I, J) :-
    J is 1 + (I * 7919) mod W.objects.

sample_furniture(W, I, F) :-
    F is 1 + (I * 7) mod W.furniture.

asserted_statement(W, I, S) :-
    sample_object(W, I, J),
    placement(W, J, Property, Target),
    format(string(S), "obj~d ~w ~w", [J, Property, Target]).

%   update: the opposite of the object's initial visibility.

update_statement(W, I, S) :-
    sample_object(W, I, J),
    visible(J, V0),
    (   V0 == true
    ->  V = false
    ;   V = true
    ),
    format(string(S), "obj~d isVisible ~w", [J, V]).

		 /*******************************
		 *          CONCURRENCY         *
		 *******************************/

%   concurrency(+Port, +EchoPort, +Params, +World, -Figures): 8 clients,
%   each on its own connection, each sending up to `samples` requests
%   (a mix: check asserted, check inferred type, find 1 pattern, add 1)
%   as fast as they are answered; the same clients against the echo
%   server.

concurrency(Port, EchoPort, Params, W, concurrent{clients:N, server:Server, echo:Echo,
                                                   ratio:Ratio}) :-
    N = 8,
    progress("size ~D: ~d concurrent clients", [W.size, N]),
    clients(Port, N, Params, W, Server),
    clients(EchoPort, N, Params, W, Echo),
    Ratio is Echo.per_s / Server.per_s.

clients(Port, N, Params, W, result{requests:Count, seconds:Seconds, per_s:PerSecond,
                                   stats:Stats}) :-
    message_queue_create(Queue),
    get_time(Now),
    Deadline is Now + Params.budget + 60,
    numlist(1, N, Ks),
    maplist(start_client(Port, Queue, Params, W), Ks, Threads),
    maplist(ready(Queue, Deadline), Ks),
    get_time(T0),
    maplist([T]>>thread_send_message(T, go), Threads),
    maplist(client_result(Queue, Deadline), Ks, Results),
    maplist(thread_join, Threads),
    message_queue_destroy(Queue),
    (   memberchk(failed(E), Results)
    ->  throw(E)
    ;   true
    ),
    pairs_keys_values(Results, Ends, TimeLists),
    max_list(Ends, T1),
    append(TimeLists, Times),
    length(Times, Count),
    Seconds is T1 - T0,
    PerSecond is Count / Seconds,
    bench_stats(Times, Stats).

start_client(Port, Queue, Params, W, K, Thread) :-
    thread_create(client(Port, Queue, Params, W, K), Thread, []).

ready(Queue, Deadline, _) :-
    (   thread_get_message(Queue, ready(_), [deadline(Deadline)])
    ->  true
    ;   throw(bench_failed(clients, not_ready))
    ).

client_result(Queue, Deadline, _, Result) :-
    (   thread_get_message(Queue, done(Result), [deadline(Deadline)])
    ->  true
    ;   throw(bench_failed(clients, no_result))
    ).

client(Port, Queue, Params, W, K) :-
    (   catch(client_run(Port, Queue, Params, W, K, Result0), E,
              Result0 = failed(E))
    ->  Result = Result0
    ;   Result = failed(bench_failed(client, K))
    ),
    thread_send_message(Queue, done(Result)).

client_run(Port, Queue, Params, W, K, End-Times) :-
    bench_with_connection(
        Port, C,
        ( thread_send_message(Queue, ready(K)),
          thread_get_message(go),
          bench_measure(Params.samples, Params.budget, I,
                        bench_call(C, Method, Args, _, 120),
                        mix_request(W, K, I, Method, Args),
                        Times),
          get_time(End)
        )).

mix_request(W, K, I, Method, Params) :-
    Case is I mod 4,
    J is I * 8 + K,
    (   Case =:= 0
    ->  Method = check,
        asserted_statement(W, J, S),
        Params = [[S]]
    ;   Case =:= 1
    ->  Method = check,
        sample_object(W, J, O),
        format(string(S), "obj~d rdf:type Artifact", [O]),
        Params = [[S]]
    ;   Case =:= 2
    ->  Method = find,
        sample_furniture(W, J, F),
        format(string(P), "?o isAt furniture~d", [F]),
        Params = ["o", [P]]
    ;   Method = add,
        furniture_of(W, J, F),
        format(string(S), "client~d_~d isOn furniture~d", [K, I, F]),
        Params = [[S]]
    ).

		 /*******************************
		 *            EVENTS            *
		 *******************************/

%   event_figures(+Conn, +Params, +World, -Events): the latency of a
%   NEW_INSTANCE event (from sending the add that causes it to reading
%   the event) with 1,000 other NEW_INSTANCE watchers registered:
%
%     - `same`: the 1,000 watch `?o isOn furnitureK` (K = 1..1000),
%       the very predicate the measured changes use, so each change
%       re-evaluates all of them (the hard case, used by the target);
%     - `other`: the 1,000 watch `?o isIn container_K`, a predicate the
%       changes do not touch.
%
%   The measured watcher, `?o isOn bench_table`, is registered last.  A
%   sample whose event does not come within 5 s, or comes with another
%   content, is missed.

event_figures(C, Params, W, events{watchers:1000, same:Same, other:Other}) :-
    progress("size ~D: events, 1000 watchers on the changed predicate", [W.size]),
    watchers_latency(C, Params, "[?o isOn furniture~d]", same, Same),
    progress("size ~D: events, 1000 watchers on another predicate", [W.size]),
    watchers_latency(C, Params, "[?o isIn container_~d]", other, Other).

watchers_latency(C, Params, Format, Tag, result{register:Register, latency:Latency,
                                                 after_ok:AfterOk, missed:Missed}) :-
    findall(T, ( between(1, 1000, K),
                 format(string(P), Format, [K]),
                 bench_time(call_ok(C, registerEvent,
                                    ["NEW_INSTANCE", "ON_TRUE", "o", P]), T)
               ), RegTimes),
    bench_stats(RegTimes, Register),
    format(string(Table), "[?o isOn bench_table_~w]", [Tag]),
    call_ok(C, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", Table], Id),
    get_time(Now),
    Deadline is Now + Params.budget,
    latencies(C, Id, Tag, 1, Params.samples, Deadline, Samples),
    findall(L, member(L-_, Samples), Latencies),
    findall(A, member(_-A, Samples), After),
    aggregate_all(count, member(missed(_), Samples), Missed),
    bench_stats(Latencies, Latency),
    bench_stats(After, AfterOk),
    call_ok(C, clearEvents, []).

latencies(C, Id, Tag, I, N, Deadline, Samples) :-
    (   I > N
    ->  Samples = []
    ;   I > 20,
        get_time(Now),
        Now > Deadline
    ->  Samples = []
    ;   latency(C, Id, Tag, I, Sample),
        Samples = [Sample|Rest],
        I1 is I + 1,
        latencies(C, Id, Tag, I1, N, Deadline, Rest)
    ).

latency(C, Id, Tag, I, Sample) :-
    format(atom(Obj), 'ev_~w_~d', [Tag, I]),
    format(string(Stmt), "[~w isOn bench_table_~w]", [Obj, Tag]),
    format(string(Expected), "[\"~w\"]", [Obj]),
    get_time(T0),
    bench_send(C, add, [Stmt]),
    bench_receive(C, Reply, 120),
    (   Reply = ok(_)
    ->  get_time(TOk),
        bench_receive(C, Event, 5),
        get_time(T1),
        (   Event = event(Id, Expected)
        ->  Latency is (T1 - T0) * 1.0e6,
            After is (T1 - TOk) * 1.0e6,
            Sample = Latency-After
        ;   Sample = missed(Event)
        )
    ;   Sample = missed(Reply)
    ).

		 /*******************************
		 *           STARTUP            *
		 *******************************/

%   startup_figures(-Startup): wall time from starting `swipl
%   server/oro_server.pl --port=0` to its listening line, 5 runs, beside
%   a bare `swipl -g halt`; the server's memory once listening.

startup_figures(startup{runs:5, stats:Stats, memory:Memory, floor:Floor, ratio:Ratio}) :-
    progress("startup to listening", []),
    findall(T-M, ( between(1, 5, _),
                   startup_time([], T, M)
                 ), Runs),
    pairs_keys_values(Runs, Times, [Memory|_]),
    bench_stats(Times, Stats),
    findall(T, ( between(1, 5, _),
                 bench_time(bare_swipl, T)
               ), FloorTimes),
    bench_stats(FloorTimes, Floor),
    Ratio is Stats.median / Floor.median,
    ms_text(Stats.median, Median),
    ms_text(Stats.max, Max),
    ms_text(Floor.median, FloorMedian),
    format("~nStartup to listening (5 runs): median ~w, max ~w; \c
            bare swipl -g halt ~w (~1fx); server RSS ~w kB~n",
           [Median, Max, FloorMedian, Ratio, Memory.rss_kb]).

%   startup_time(+Args, -Micros, -Memory): start the server with Args,
%   time until its listening line, read its memory, kill it.

startup_time(Args, Micros, Memory) :-
    bench_server_script(Server),
    get_time(T0),
    setup_call_cleanup(
        process_create(path(swipl), [Server, '--port=0'|Args],
                       [stdout(pipe(Out)), process(Pid)]),
        ( read_line_to_string(Out, Line),
          get_time(T1),
          (   string(Line),
              sub_string(Line, 0, _, _, "oro listening on")
          ->  true
          ;   throw(bench_failed(startup, Line))
          ),
          bench_memory(Pid, Memory)
        ),
        ( catch(process_kill(Pid), _, true),
          process_wait(Pid, _),
          close(Out)
        )),
    Micros is (T1 - T0) * 1.0e6.

bare_swipl :-
    process_create(path(swipl), ['-g', halt], [process(Pid)]),
    process_wait(Pid, _).

		 /*******************************
		 *        TURTLE LOADING        *
		 *******************************/

%   turtle_figures(+Size, -Turtle): the robot's world of Size written as
%   Turtle to a temporary file; the server's startup to listening with
%   --ontology=FILE (one run), and rdf_load/2 of the file in this
%   process (its floor).

turtle_figures(Size, turtle{size:Size, triples:Triples, bytes:Bytes,
                            startup_s:Startup, load_s:Load, memory:Memory,
                            floor_s:Floor, ratio:Ratio}) :-
    world(Size, W),
    progress("Turtle: writing the world of ~D triples", [Size]),
    setup_call_cleanup(
        tmp_file_stream(File, Stream, [extension(ttl), encoding(utf8)]),
        write_turtle(Stream, W),
        close(Stream)),
    call_cleanup(turtle_load(File, Triples, Bytes, Startup, Memory, Floor),
                 delete_file(File)),
    startup_baseline(Baseline),
    Load is Startup - Baseline,
    Ratio is Load / Floor,
    format("~nTurtle: ~D triples (~1f MB): server startup to listening \c
            ~2f s (~2f s beyond a plain startup), RSS ~w kB; rdf_load/2 \c
            in process ~2f s (~1fx)~n",
           [Triples, Bytes / 1048576, Startup, Load, Memory.rss_kb, Floor, Ratio]).

turtle_load(File, Triples, Bytes, Startup, Memory, Floor) :-
    size_file(File, Bytes),
    progress("Turtle: server startup with --ontology (~D bytes)", [Bytes]),
    format(atom(Arg), '--ontology=~w', [File]),
    startup_time([Arg], Micros, Memory),
    Startup is Micros / 1.0e6,
    progress("Turtle: rdf_load/2 in this process", []),
    get_time(T0),
    rdf_load(File, [graph(bench_turtle), format(turtle), silent(true)]),
    get_time(T1),
    rdf_graph_property(bench_turtle, triples(Triples)),
    rdf_unload_graph(bench_turtle),
    Floor is T1 - T0.

%   startup_baseline(-Seconds): one plain startup, to subtract.

startup_baseline(Seconds) :-
    startup_time([], Micros, _),
    Seconds is Micros / 1.0e6.

write_turtle(Out, W) :-
    format(Out, "@prefix : <http://kb.openrobots.org#> .~n\c
                 @prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .~n~n", []),
    forall(between(1, W.objects, I),
           ( unit_statements(W, I, Statements),
             forall(member(S, Statements), turtle_triple(Out, S))
           )).

%   turtle_triple(+Out, +Statement): one of the world's statements
%   (subject, predicate, object separated by single spaces; the object
%   a name, a boolean or a quoted string) as a Turtle triple.

turtle_triple(Out, Statement) :-
    sub_string(Statement, B1, 1, _, " "),
    !,
    sub_string(Statement, 0, B1, _, S),
    A1 is B1 + 1,
    sub_string(Statement, A1, _, 0, Rest),
    sub_string(Rest, B2, 1, _, " "),
    !,
    sub_string(Rest, 0, B2, _, P),
    A2 is B2 + 1,
    sub_string(Rest, A2, _, 0, O),
    turtle_predicate(P, TP),
    turtle_object(O, TO),
    format(Out, ":~w ~w ~w .~n", [S, TP, TO]).

turtle_predicate("rdf:type", a) :- !.
turtle_predicate("rdfs:label", 'rdfs:label') :- !.
turtle_predicate(P, TP) :-
    atom_concat(':', P, TP).

turtle_object(O, O) :-
    (   sub_string(O, 0, 1, _, "\"")
    ;   O == "true"
    ;   O == "false"
    ),
    !.
turtle_object(O, TO) :-
    atom_concat(':', O, TO).

		 /*******************************
		 *            REPLAY            *
		 *******************************/

%   replay_figures(+Log, -Replay): the recorded robot session replayed
%   on a fresh server started with the experiment's robot id, its human
%   partner declared first (as the experiment's scenario ontology did):
%   every request, each client thread on its own connection (opened
%   beforehand), in log order, one at a time, no sleeps.  Total time
%   and each request's round trip; the events pushed meanwhile are read
%   and counted.

replay_figures(Log, Replay) :-
    (   exists_file(Log)
    ->  progress("replay of ~w", [Log]),
        bench_log_requests(Log, Requests),
        bench_with_server(['--robot-id=JIDOKUKA_ROBOT'], Port, _,
                          bench_with_connection(
                              Port, C,
                              ( call_ok(C, add, [["ACHILE_HUMAN1 rdf:type Human"]]),
                                wait_listed(C, ['ACHILE_HUMAN1'], 30),
                                replay(Port, Requests, Replay)
                              ))),
        print_replay(Replay)
    ;   format(user_error, "Notice: ~w not found: replay skipped.~n", [Log]),
        Replay = null
    ).

replay(Port, Requests, replay{requests:N, connections:NConn, seconds:Seconds,
                              stats:Stats, ok:NOk, errors:Errors,
                              unanswered:NNone, unparsed:NBad, events:NEvents}) :-
    include([R]>>(R = request(_, _, _)), Requests, Good),
    length(Requests, NAll),
    length(Good, N),
    NBad is NAll - N,
    findall(T, member(request(T, _, _), Good), Threads0),
    sort(Threads0, Threads),
    length(Threads, NConn),
    with_connections(Threads, Port, Conns,
                     ( get_time(T0),
                       maplist(replay_request(Conns), Good, Outcomes),
                       get_time(T1)
                     )),
    Seconds is T1 - T0,
    findall(M, member(o(M, _, _), Outcomes), Times),
    bench_stats(Times, Stats),
    aggregate_all(count, member(o(_, ok, _), Outcomes), NOk),
    findall(Name, member(o(_, error(Name), _), Outcomes), Names0),
    msort(Names0, Names),
    clumped(Names, Errors0),
    findall(_{exception:E, count:K}, member(E-K, Errors0), Errors),
    aggregate_all(count, member(o(_, none, _), Outcomes), NNone),
    aggregate_all(sum(E), member(o(_, _, E), Outcomes), NEvents).

%   with_connections(+Threads, +Port, -Conns, :Goal): Goal with one
%   connection per thread name, Conns a list of Thread-Conn.

with_connections([], _, [], Goal) :-
    once(Goal).
with_connections([T|Ts], Port, [T-C|Cs], Goal) :-
    bench_with_connection(Port, C, with_connections(Ts, Port, Cs, Goal)).

replay_request(Conns, request(Thread, Method, Params), o(Micros, Kind, Events)) :-
    memberchk(Thread-C, Conns),
    get_time(T0),
    bench_request(C, Method, Params, reply(Message, Events), 30),
    get_time(T1),
    Micros is (T1 - T0) * 1.0e6,
    (   Message = ok(_)
    ->  Kind = ok
    ;   Message = error(Name, _)
    ->  Kind = error(Name)
    ;   Kind = none
    ).

print_replay(R) :-
    us_text(R.stats.median, Median),
    us_text(R.stats.p99, P99),
    us_text(R.stats.max, Max),
    format("~nReplay of the 2011 robot session: ~d requests on ~d connections \c
            in ~3f s; per request median ~w, p99 ~w, max ~w; ~d ok, \c
            ~d unanswered, ~d unparsed, ~d events read~n",
           [R.requests, R.connections, R.seconds, Median, P99, Max, R.ok,
            R.unanswered, R.unparsed, R.events]),
    forall(member(E, R.errors),
           format("   error ~w: ~d~n", [E.exception, E.count])).

		 /*******************************
		 *            REPORT            *
		 *******************************/

print_size(S) :-
    format("~n== ~D asserted triples (~D sent: ~D objects, ~D pieces of \c
            furniture, ~D rooms, ~d agents with ~D beliefs) ==~n",
           [S.triples, S.load.statements, S.world.objects, S.world.furniture,
            S.world.rooms, S.world.agents, S.load.belief_statements]),
    format("server memory: VmRSS ~w kB after the load, VmHWM ~w kB at the end~n~n",
           [S.memory_loaded.rss_kb, S.memory_end.hwm_kb]),
    row(operation, median, p99, max, 'x floor', 'per second'),
    stats_row('echo round trip, 1 statement (floor)', S.echo.one, -, -),
    stats_row('echo round trip, 100 statements (floor)', S.echo.batch, -, -),
    Floor = S.rdf_assert_per_s,
    rate_row('bulk add, world load (x rdf_assert)', S.load.robot_per_s, Floor),
    rate_row('addForAgent, the beliefs (x rdf_assert)', S.load.belief_per_s, Floor),
    stats_row('  a batch of 100 of the load (x echo)', S.load.batch,
              S.echo.batch.median, -),
    forall(member(Op, S.operations),
           stats_row(Op.label, Op.stats, Op.floor_median, Op.per_s)),
    C = S.concurrent,
    stats_row('8 clients, mixed requests', C.server.stats,
              C.echo.stats.median, C.server.per_s),
    stats_row('8 clients against echo (floor)', C.echo.stats, -, C.echo.per_s),
    E = S.events,
    event_row('event, 1000 watchers on its predicate', E.same, S.echo.one.median),
    event_row('event, 1000 watchers elsewhere', E.other, S.echo.one.median),
    flush_output.

%   row(+Label, +Median, +P99, +Max, +Ratio, +PerSecond): one line of the
%   table, the cells already texts.

row(Label, Median, P99, Max, Ratio, PerSecond) :-
    format("~w~t~46|~w~t~11+~w~t~11+~w~t~11+~w~t~9+~w~n",
           [Label, Median, P99, Max, Ratio, PerSecond]).

stats_row(Label, Stats, FloorMedian, PerSecond) :-
    us_text(Stats.median, M),
    us_text(Stats.p99, P),
    us_text(Stats.max, X),
    (   number(FloorMedian),
        number(Stats.median)
    ->  ratio_text(Stats.median / FloorMedian, R)
    ;   R = "-"
    ),
    count_text(PerSecond, PS),
    row(Label, M, P, X, R, PS).

rate_row(Label, Rate, FloorRate) :-
    ratio_text(FloorRate / Rate, R),
    count_text(Rate, PS),
    row(Label, -, -, -, R, PS).

event_row(Label, Result, EchoMedian) :-
    Stats = Result.latency,
    us_text(Stats.median, M),
    us_text(Stats.p99, P),
    us_text(Stats.max, X),
    (   number(Stats.median)
    ->  ratio_text(Stats.median / EchoMedian, R)
    ;   R = "-"
    ),
    format(string(Missed), "~d missed", [Result.missed]),
    row(Label, M, P, X, R, Missed).

us_text(X, Text) :-
    bench_micros(X, Text, [units(auto)]).

ms_text(X, Text) :-
    format(string(Text), "~1f ms", [X / 1000]).

ratio_text(Expr, Text) :-
    X is Expr,
    format(string(Text), "~1fx", [X]).

count_text(X, Text) :-
    (   number(X)
    ->  format(string(Text), "~0f", [X])
    ;   Text = "-"
    ).

		 /*******************************
		 *           SCALING            *
		 *******************************/

%   scaling(+PerSize, -Scaling): the figures of the largest size
%   against those at 100,000 triples (null unless both were measured):
%   each operation's median, the bulk rate, the event latency and the
%   8 clients' throughput, as a ratio larger than 1 when the larger
%   world is slower.

scaling(PerSize, Scaling) :-
    (   member(Base, PerSize),
        Base.triples =:= 100000,
        last(PerSize, Large),
        Large.triples > 100000
    ->  findall(R, scaling_row(Base, Large, R), Rows),
        Scaling = scaling{from:100000, to:Large.triples, rows:Rows},
        format("~nScaling: ~D against 100,000 triples (slower by)~n",
               [Large.triples]),
        forall(member(R, Rows),
               ( ratio_text(R.ratio, T),
                 format("   ~w~t~46|~w~n", [R.label, T])
               ))
    ;   Scaling = null
    ).

scaling_row(Base, Large, row{key:Key, label:Label, ratio:Ratio}) :-
    member(Op, Large.operations),
    member(BaseOp, Base.operations),
    BaseOp.key == Op.key,
    Key = Op.key,
    Label = Op.label,
    Ratio is Op.stats.median / BaseOp.stats.median.
scaling_row(Base, Large, row{key:bulk_add, label:"bulk add (rate)", ratio:Ratio}) :-
    Ratio is Base.load.robot_per_s / Large.load.robot_per_s.
scaling_row(Base, Large, row{key:event_same, label:"event, 1000 watchers on its predicate",
                             ratio:Ratio}) :-
    number(Base.events.same.latency.median),
    number(Large.events.same.latency.median),
    Ratio is Large.events.same.latency.median / Base.events.same.latency.median.
scaling_row(Base, Large, row{key:concurrent, label:"8 clients (throughput)", ratio:Ratio}) :-
    Ratio is Base.concurrent.server.per_s / Large.concurrent.server.per_s.

		 /*******************************
		 *           TARGETS            *
		 *******************************/

%   targets(+PerSize, +Startup, +Turtle, +Replay, +Scaling, -Targets):
%   the targets of the issue, each with the figure measured and whether
%   it is met (true, false, or null when not measured in this run).
%   Socket figures at 100,000 triples (else the largest size measured).

targets(PerSize, Startup, Turtle, Replay, Scaling, Targets) :-
    (   member(Ref, PerSize),
        Ref.triples =:= 100000
    ->  true
    ;   last(PerSize, Ref)
    ),
    findall(T, target(Ref, PerSize, Startup, Turtle, Replay, Scaling, T), Targets),
    format("~nTargets (socket figures at ~D triples; medians unless said)~n",
           [Ref.triples]),
    forall(member(T, Targets),
           ( verdict(T.pass, V0),
             (   get_dict(aim, T, Aim)
             ->  verdict(Aim, AimV),
                 format(string(V), "~w (aim: ~w)", [V0, AimV])
             ;   V = V0
             ),
             format("   ~w~t~72|~w~t~24+~w~n", [T.target, T.figure, V])
           )).

verdict(true, 'PASS').
verdict(false, 'MISS').
verdict(null, 'not measured').

target(Ref, _, _, _, _, _, target{target:Target, figure:Figure, pass:Pass, aim:Aim}) :-
    member(Key, [check_asserted, check_type, check_property, find_1, add_1,
                 lookup_label, lookup_name]),
    member(Op, Ref.operations),
    Op.key == Key,
    format(string(Target), "~w: within 3x echo (aim < 100 us)", [Op.label]),
    us_text(Op.stats.median, M),
    format(string(Figure), "~w = ~1fx echo", [M, Op.ratio]),
    bool(Op.ratio =< 3, Pass),
    bool(Op.stats.median < 100, Aim).
target(Ref, _, _, _, _, _, target{target:"bulk add: >= 100,000 statements/s (batches of 100)",
                                  figure:Figure, pass:Pass}) :-
    Rate = Ref.load.robot_per_s,
    RateInt is integer(Rate),
    format(string(Figure), "~D stmt/s", [RateInt]),
    bool(Rate >= 100000, Pass).
target(Ref, _, _, _, _, _, target{target:"event latency, 1000 watchers: median < 1 ms",
                                  figure:Figure, pass:Pass}) :-
    L = Ref.events.same.latency,
    us_text(L.median, Figure),
    bool(L.median < 1000, Pass).
target(Ref, _, _, _, _, _, target{target:"event latency, 1000 watchers: p99 < 5 ms",
                                  figure:Figure, pass:Pass}) :-
    L = Ref.events.same.latency,
    us_text(L.p99, Figure),
    bool(L.p99 < 5000, Pass).
target(Ref, _, _, _, _, _, target{target:"event latency, 1000 watchers: 0 missed",
                                  figure:Figure, pass:Pass}) :-
    Missed is Ref.events.same.missed + Ref.events.other.missed,
    format(string(Figure), "~d missed", [Missed]),
    bool(Missed =:= 0, Pass).
target(_, _, Startup, _, _, _, target{target:"startup to listening, bundled ontology: < 0.5 s",
                                      figure:Figure, pass:Pass}) :-
    ms_text(Startup.stats.median, Figure),
    bool(Startup.stats.median < 500000, Pass).
target(_, _, _, Turtle, _, _, target{target:"loading 1M triples of Turtle: < 10 s",
                                     figure:Figure, pass:Pass}) :-
    (   Turtle.size >= 1000000
    ->  format(string(Figure), "~2f s to listening", [Turtle.startup_s]),
        bool(Turtle.startup_s < 10, Pass)
    ;   format(string(Figure), "(largest size ~D)", [Turtle.size]),
        Pass = null
    ).
target(_, PerSize, _, _, _, _, target{target:"RSS at 1M asserted triples: < 1 GiB",
                                      figure:Figure, pass:Pass}) :-
    (   member(S, PerSize),
        S.triples >= 1000000
    ->  RSS = S.memory_loaded.rss_kb,
        format(string(Figure), "~1f MiB", [RSS / 1024]),
        bool(RSS < 1048576, Pass)
    ;   Figure = "(no 1M size)",
        Pass = null
    ).
target(_, _, _, _, Replay, _, target{target:"robot session replay: < 1 s in total",
                                     figure:Figure, pass:Pass}) :-
    (   Replay == null
    ->  Figure = "(no log)",
        Pass = null
    ;   format(string(Figure), "~3f s", [Replay.seconds]),
        bool(Replay.seconds < 1, Pass)
    ).
target(_, _, _, _, _, Scaling, target{target:Target, figure:Figure, pass:Pass}) :-
    Scaling \== null,
    member(Row, Scaling.rows),
    format(string(Target), "~D vs 100k, ~w: <= 2x", [Scaling.to, Row.label]),
    ratio_text(Row.ratio, Figure),
    bool(Row.ratio =< 2, Pass).

bool(Goal, Bool) :-
    (   call(Goal)
    ->  Bool = true
    ;   Bool = false
    ).

		 /*******************************
		 *             JSON             *
		 *******************************/

write_json(File, Results) :-
    setup_call_cleanup(
        open(File, write, Out, [encoding(utf8)]),
        ( json_write_dict(Out, Results, [width(100)]),
          nl(Out)
        ),
        close(Out)).
