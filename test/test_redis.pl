:- use_module(library(plunit)).
:- use_module(library(process)).
:- use_module(library(socket)).
:- use_module(library(filesex)).
:- use_module(library(readutil)).
:- use_module(library(redis)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(oro_test_support).
:- use_module(oro_test_client).

/*  Tests for several robots sharing knowledge through Redis (issue
    #41): each test starts its own redis-server on a free loopback port
    with a temporary directory, and oro servers as child processes
    (in-process servers would share one rdf_db store).

      - publish and follow: a fact added on robot_a is seen in robot_b's
        model robot_a, its removal too; robot_b publishes none of it
        back; a watcher of robot_b on that model fires;
      - restart: robot_b with --db, killed with kill -9, catches up
        from the last entry it applied, nothing missing or doubled;
      - Redis killed and restarted mid-stream: robot_a keeps answering,
        then publishes what it buffered, robot_b catches up;
      - two writers to the world model end with the same value of a
        functional property, the one written last in the stream;
      - a follower started late (without --db) builds the model from
        the stream.

    When redis-server is not installed the tests are skipped, with a
    notice.
*/

redis_available :-
    absolute_file_name(path('redis-server'), _,
                       [access(execute), file_errors(fail)]).

:- (   redis_available
   ->  true
   ;   print_message(warning,
                     format("test_redis: redis-server is not installed \c
                             (.ci/run installs it): Redis tests skipped", []))
   ).

		 /*******************************
		 *           FIXTURES           *
		 *******************************/

%   redis_start(-Redis): a redis-server on a free loopback port, with an
%   append-only file in a new temporary directory.

redis_start(redis(Pid, Port, Dir)) :-
    free_port(Port),
    tmp_file(redis, Dir),
    make_directory(Dir),
    redis_start(Port, Dir, Pid).

redis_start(Port, Dir, Pid) :-
    process_create(path('redis-server'),
                   [ '--port', Port, '--bind', '127.0.0.1', '--dir', Dir,
                     '--save', '', '--appendonly', yes,
                     '--appendfsync', always
                   ],
                   [ stdout(null), stderr(null), process(Pid) ]),
    assertion(test_wait_until(redis_up(Port), 10)).

redis_up(Port) :-
    catch(setup_call_cleanup(
              redis_connect('127.0.0.1':Port, C, [reconnect(false)]),
              redis(C, ping, status(pong)),
              redis_disconnect(C)),
          _, fail).

redis_stop(redis(Pid, _, Dir)) :-
    kill_process(Pid),
    delete_directory_and_contents(Dir).

kill_process(Pid) :-
    catch(process_kill(Pid, kill), _, true),
    catch(process_wait(Pid, _), _, true).

free_port(Port) :-
    tcp_socket(S),
    tcp_bind(S, '127.0.0.1':Port),
    tcp_close_socket(S).

redis_url(redis(_, Port, _), URL) :-
    format(atom(URL), '--redis=redis://127.0.0.1:~w', [Port]).

%   node_start(+Redis, +Args, -Node): an oro server, child process.

node_start(Redis, Args, node(Pid, Conn)) :-
    redis_url(Redis, URL),
    test_checkout_path('server/oro_server.pl', Server),
    (   getenv('ORO_REDIS_TEST_LOG', Log)   % the nodes' stderr, to debug
    ->  open(Log, append, Err),
        ErrSpec = stderr(stream(Err))
    ;   ErrSpec = stderr(null)
    ),
    process_create(path(swipl),
                   [Server, '--port=0', '--no-kb', '--no-http', URL|Args],
                   [ stdout(pipe(Out)), ErrSpec, process(Pid) ]),
    read_line_to_string(Out, Line),
    close(Out),
    (   split_string(Line, ":", " ", Parts),
        last(Parts, PortText),
        number_string(Port, PortText)
    ->  oro_connect(Port, Conn)
    ;   kill_process(Pid),
        throw(node_did_not_start(Args, Line))
    ).

node_stop(node(Pid, Conn)) :-
    catch(oro_disconnect(Conn), _, true),
    kill_process(Pid).

call_ok(node(_, Conn), Method, Params, Value) :-
    oro_call(Conn, Method, Params, Reply),
    test_expect_ok(Method-Params, Reply, Text),
    (   Text == ""
    ->  Value = []
    ;   test_json(Text, Value)
    ).

add(Node, Statements) :-
    test_set_text(Statements, Text),
    call_ok(Node, add, [Text], _).

remove(Node, Statements) :-
    test_set_text(Statements, Text),
    call_ok(Node, remove, [Text], _).

find(Node, Model, Pattern, Sorted) :-
    call_ok(Node, findForAgent, [Model, '?x', Pattern], Names),
    msort(Names, Sorted).

sees(Node, Model, Pattern, Expected) :-
    catch(find(Node, Model, Pattern, Expected),
          test_unexpected_reply(_, _), fail).   % no such agent yet

wait_sees(Node, Model, Pattern, Expected) :-
    msort(Expected, Sorted),
    test_wait_until(sees(Node, Model, Pattern, Sorted), 20).

cups(From, To, Names) :-
    numlist(From, To, Ns),
    maplist([N, Name]>>format(string(Name), "cup~d", [N]), Ns, Names).

cup_statements(Names, Statements) :-
    maplist([C, S]>>format(string(S), "~w isIn box1", [C]), Names,
            Statements).

:- meta_predicate with_redis(1).

with_redis(Goal) :-
    setup_call_cleanup(redis_start(Redis), call(Goal, Redis),
                       redis_stop(Redis)).

:- meta_predicate with_nodes(+, +, +, 2).

%   with_nodes(+Redis, +ArgsA, +ArgsB, :Goal): call(Goal, A, B) with
%   two nodes started with ArgsA and ArgsB, stopped afterwards.

with_nodes(Redis, ArgsA, ArgsB, Goal) :-
    setup_call_cleanup(
        node_start(Redis, ArgsA, A),
        setup_call_cleanup(
            node_start(Redis, ArgsB, B),
            call(Goal, A, B),
            node_stop(B)),
        node_stop(A)).

stream_entries(redis(_, Port, _), Stream, Entries) :-
    setup_call_cleanup(
        redis_connect('127.0.0.1':Port, C, [reconnect(false)]),
        redis(C, xrange(Stream, -, +), Entries),
        redis_disconnect(C)).

		 /*******************************
		 *        PUBLISH/FOLLOW        *
		 *******************************/

:- begin_tests(redis_follow, [condition(redis_available)]).

test(add_and_remove_replicated) :-
    with_redis(add_and_remove).

add_and_remove(Redis) :-
    with_nodes(Redis, ['--node=robot_a'],
               ['--node=robot_b', '--follow=robot_a'], add_and_remove(Redis)).

add_and_remove(Redis, A, B) :-
    add(A, ["cup1 rdf:type Cup", "cup1 isOn table1"]),
    assertion(wait_sees(B, robot_a, '[?x isOn table1]', ["cup1"])),
    assertion(wait_sees(B, robot_a, '[?x rdf:type Cup]', ["cup1"])),
    find(B, myself, '[?x isOn table1]', Own),
    assertion(Own == []),
    remove(A, ["cup1 isOn table1"]),
    assertion(wait_sees(B, robot_a, '[?x isOn table1]', [])),
    assertion(sees(B, robot_a, '[?x rdf:type Cup]', ["cup1"])),
    stream_entries(Redis, 'oro:node:robot_b', Echoes),
    assertion(\+ ( member([_, Fields], Echoes),
                   member(V, Fields),
                   sub_atom(V, _, _, _, cup1)
                 )),
    call_ok(B, reset, [], _),                   % robot_b forgets robot_a
    assertion(wait_sees(B, robot_a, '[?x rdf:type Cup]', ["cup1"])),
    assertion(sees(B, robot_a, '[?x isOn table1]', [])).

test(bad_options_refused) :-
    test_cli_server(['--redis=http://x', '--node=n'], Port1, true, Err1),
    assertion(Port1 == none),
    assertion(sub_string(Err1, _, _, _, "redis_url")),
    test_cli_server(['--redis=redis://127.0.0.1:1'], Port2, true, Err2),
    assertion(Port2 == none),
    assertion(sub_string(Err2, _, _, _, "node")).

test(applied_change_fires_watcher) :-
    with_redis(fires_watcher).

fires_watcher(Redis) :-
    with_nodes(Redis, ['--node=robot_a'],
               ['--node=robot_b', '--follow=robot_a'], fires_watcher).

fires_watcher(A, B) :-
    add(A, ["ball1 rdf:type Ball"]),
    assertion(wait_sees(B, robot_a, '[?x rdf:type Ball]', ["ball1"])),
    B = node(_, Conn),
    oro_call(Conn, registerEventForAgent,
             [robot_a, 'NEW_INSTANCE', 'ON_TRUE', '?x', '[?x isOn table1]'], Reply),
    assertion(Reply = ok(_)),
    add(A, ["ball1 isOn table1"]),
    oro_next_event(Conn, event(_, Content), 20),
    assertion(sub_string(Content, _, _, _, "ball1")).

:- end_tests(redis_follow).

		 /*******************************
		 *     RESTART, PARTITIONS      *
		 *******************************/

:- begin_tests(redis_recovery, [condition(redis_available)]).

%   robot_b follows robot_a with --db, is killed with kill -9, misses
%   10,000 changes (and a removal), and restarts: it must then see
%   exactly robot_a's cups, none missing, none removed still there.

test(restart_catches_up_from_db) :-
    with_redis(restart_catches_up).

restart_catches_up(Redis) :-
    tmp_file(oro_db, Db),
    format(atom(DbArg), '--db=~w', [Db]),
    BArgs = ['--node=robot_b', '--follow=robot_a', DbArg],
    setup_call_cleanup(
        node_start(Redis, ['--node=robot_a'], A),
        ( cups(1, 50, First),
          cup_statements(First, S1),
          add(A, S1),
          node_start(Redis, BArgs, B1),
          assertion(wait_sees(B1, robot_a, '[?x isIn box1]', First)),
          node_stop(B1),                        % kill -9
          cups(51, 10050, Later),               % 10,000 changes missed
          forall(member(S, Later),
                 ( cup_statements([S], [St]), add(A, [St]) )),
          remove(A, ["cup7 isIn box1"]),
          setup_call_cleanup(
              node_start(Redis, BArgs, B2),
              ( append(First, Later, All0),
                delete(All0, "cup7", All),
                assertion(wait_sees(B2, robot_a, '[?x isIn box1]', All))
              ),
              node_stop(B2))
        ),
        ( node_stop(A),
          delete_directory_and_contents(Db)
        )).

test(redis_killed_mid_stream) :-
    with_redis(redis_killed).

redis_killed(Redis) :-
    with_nodes(Redis, ['--node=robot_a'],
               ['--node=robot_b', '--follow=robot_a'], redis_killed(Redis)).

redis_killed(redis(Pid, Port, Dir), A, B) :-
    cups(1, 20, First),
    cup_statements(First, S1),
    add(A, S1),
    assertion(wait_sees(B, robot_a, '[?x isIn box1]', First)),
    kill_process(Pid),
    cups(21, 60, Later),
    forall(member(C, Later),
           ( cup_statements([C], [St]), add(A, [St]) )),   % still ok
    find(A, myself, '[?x isIn box1]', Local),
    append(First, Later, All),
    msort(All, AllSorted),
    assertion(Local == AllSorted),
    redis_start(Port, Dir, Pid2),
    call_cleanup(assertion(wait_sees(B, robot_a, '[?x isIn box1]', All)),
                 kill_process(Pid2)).

test(late_follower_builds_from_stream) :-
    with_redis(late_follower).

late_follower(Redis) :-
    setup_call_cleanup(
        node_start(Redis, ['--node=robot_a'], A),
        ( cups(1, 40, Cups),
          cup_statements(Cups, S),
          add(A, S),
          remove(A, ["cup3 isIn box1"]),
          delete(Cups, "cup3", Expected),
          setup_call_cleanup(
              node_start(Redis, ['--node=robot_c', '--follow=*'], C),
              assertion(wait_sees(C, robot_a, '[?x isIn box1]', Expected)),
              node_stop(C))
        ),
        node_stop(A)).

:- end_tests(redis_recovery).

		 /*******************************
		 *            WORLD             *
		 *******************************/

:- begin_tests(redis_world, [condition(redis_available)]).

test(two_writers_converge) :-
    with_redis(two_writers).

two_writers(Redis) :-
    Args = ['--share-world', '--follow=*'],
    with_nodes(Redis, ['--node=robot_a'|Args], ['--node=robot_b'|Args],
               two_writers(Redis)).

two_writers(Redis, A, B) :-
    thread_create(write_colors(A, [a1, a2, a3, a4, a5]), T1, []),
    thread_create(write_colors(B, [b1, b2, b3, b4, b5]), T2, []),
    thread_join(T1, S1),
    thread_join(T2, S2),
    assertion(S1 == true),
    assertion(S2 == true),
    last_color(Redis, Last),
    assertion(wait_sees(A, world, '[car1 hasColor ?x]', [Last])),
    assertion(wait_sees(B, world, '[car1 hasColor ?x]', [Last])),
    world_changes(Redis, Changes),
    assertion(Changes == 10).                   % none published twice

write_colors(Node, Colors) :-
    forall(member(C, Colors),
           ( format(string(S), "[car1 hasColor ~w]", [C]),
             call_ok(Node, updateForAgent, [world, S], _)
           )).

%   last_color(+Redis, -Color): the color the last world entry adding a
%   color of car1 gave it: the value that must win.

last_color(Redis, Color) :-
    test_wait_until(quiet_world(Redis), 20),
    stream_entries(Redis, 'oro:world', Entries),
    reverse(Entries, Newest),
    member([_, Fields], Newest),
    append(_, [ops, Text|_], Fields),
    term_string(Ops, Text),
    member(a(_, _, P, O), Ops),
    sub_atom(P, _, _, 0, hasColor),
    !,
    atomic_list_concat(Parts, '#', O),
    last(Parts, Name),
    atom_string(Name, Color).

%   quiet_world: the stream holds the ten changes (each update adds a
%   color none added before).

quiet_world(Redis) :-
    world_changes(Redis, N),
    N >= 10.

world_changes(Redis, N) :-
    stream_entries(Redis, 'oro:world', Entries),
    aggregate_all(count,
                  ( member([_, Fields], Entries),
                    once(( append(_, [ops, Text|_], Fields),
                           sub_atom(Text, _, _, _, hasColor)
                         ))
                  ),
                  N).

:- end_tests(redis_world).

		 /*******************************
		 *        BOUNDED BUFFER        *
		 *******************************/

/*  In process (one node only): the publishing buffer while Redis is
    unreachable, and the snapshot that replaces the dropped changes.
*/

:- use_module(library(oro)).
:- use_module(library(oro/replication/oro_redis)).


:- begin_tests(redis_buffer, [condition(redis_available)]).

test(full_buffer_then_snapshot,
     [ setup(( oro_init([]),
               set_setting(oro_redis:buffer, 5)
             )),
       cleanup(( oro_redis_stop,
                 restore_setting(oro_redis:buffer),
                 oro_reset
               ))
     ]) :-
    free_port(Port),
    format(atom(URL), 'redis://127.0.0.1:~w', [Port]),
    oro_redis_start([redis(URL), node(solo)]),
    numlist(1, 20, Ns),
    forall(member(N, Ns),
           ( format(string(S), "box~d rdf:type Box", [N]),
             oro_add(myself, [S])
           )),
    oro_redis_status(Status),
    assertion(Status.dropped >= 10),        % buffer 5, a batch taken
    assertion(Status.queued =< 5),
    once(phrase(prolog:message(oro_redis(buffer_full(5))), Lines)),
    with_output_to(string(Text),
                   print_message_lines(current_output, '', Lines)),
    assertion(sub_string(Text, _, _, _, "buffer full")),
    tmp_file(redis, Dir),
    make_directory(Dir),
    Redis = redis(Pid, Port, Dir),
    redis_start(Port, Dir, Pid),
    call_cleanup(assertion(test_wait_until(snapshot_boxes(Redis, 20), 20)),
                 ( oro_redis_stop,
                   redis_stop(Redis)
                 )).

%   snapshot_boxes(+Redis, +N): the last snapshot of solo's stream has N
%   boxes.

snapshot_boxes(Redis, N) :-
    stream_entries(Redis, 'oro:node:solo', Entries),
    reverse(Entries, Newest),
    member([_, Fields], Newest),
    append(_, [kind, snapshot|_], Fields),
    !,
    append(_, [ops, Text|_], Fields),
    term_string(Ops, Text),
    aggregate_all(count,
                  ( member(a(_, S, _, _), Ops),
                    sub_atom(S, _, _, _, box)
                  ),
                  N).

test(rebuild_publishes_nothing,
     [ setup(oro_init([])),
       cleanup(( oro_redis_stop,
                 oro_reset
               ))
     ]) :-
    with_redis(rebuild_publishes_nothing).

rebuild_publishes_nothing(Redis) :-
    Redis = redis(_, Port, _),
    format(atom(URL), 'redis://127.0.0.1:~w', [Port]),
    oro_redis_start([redis(URL), node(solo)]),
    oro_add(myself, ["box1 rdf:type Box", "box2 rdf:type Box"]),
    assertion(oro_redis_sync(20)),
    stream_entries(Redis, 'oro:node:solo', Before),
    assertion(oro_store_rebuild),
    oro_add(myself, ["box3 rdf:type Box"]),
    assertion(oro_redis_sync(20)),
    stream_entries(Redis, 'oro:node:solo', After),
    once(append(Before, [[_, Fields]], After)), % one entry more
    once(append(_, [ops, Text|_], Fields)),
    term_string(Ops, Text),
    assertion(Ops = [a(longterm, _, _, _)]),
    oro_redis_stop.

:- end_tests(redis_buffer).
