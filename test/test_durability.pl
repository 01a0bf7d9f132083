:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(oro_test_client).
:- use_module(library(oro)).

/*  Tests for durability (issue #8): the database directory of
    oro_init/1's db(Dir) and the server's --db=DIR.

      - what a model holds, agents and masked ontology triples
        included, comes back after a restart; the ontology layer is not
        journaled;
      - short-term facts keep their deadlines across a restart, and
        those past their deadline are gone at start;
      - a journal cut by a crash (a line cut in two, a change not
        committed) is repaired: a change comes back whole or not at all;
      - kill -9 of the real server at random moments loses no
        acknowledged statement and never a part of a batch (5 kills by
        default, 50 with ORO_LONG_TESTS=1);
      - SIGTERM stops the server cleanly (exit 0, everything kept);
      - journals are compacted under a stream of updates.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_durability.pl
*/

:- use_module(library(semweb/rdf_db)).
:- use_module(library(semweb/rdf_persistency)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(filesex)).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(library(settings)).
:- use_module(library(random)).
:- use_module(library(aggregate)).
:- use_module('../prolog/oro/oro_persist').

%   durability_dir(-Dir): a fresh directory name (not created).

durability_dir(Dir) :-
    tmp_file(oro_db, Dir).

durability_cleanup(Dir) :-
    oro_close,
    (   exists_directory(Dir)
    ->  delete_directory_and_contents(Dir)
    ;   true
    ).

%   durability_names(+Model, +Var, +Patterns, -Names): sorted short names.

durability_names(Model, Var, Patterns, Names) :-
    test_find(Model, Var, Patterns, Names0),
    msort(Names0, Names).

:- begin_tests(durability_restore).

test(models_come_back,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Got == [[a1, s1], [x1], [bob], false])
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, ["a1 isOn table1", "a2 isOn table1",
                     "bob rdf:type oro:Agent"]),
    oro_add(myself, ["s1 isOn table1"], episodic),
    oro_add(bob, ["x1 isOn y1"]),
    oro_remove(myself, ["a2 isOn table1"]),
    oro_init([db(Dir), commonsense(false)]),
    durability_names(myself, x, ["?x isOn table1"], OnTable),
    durability_names(bob, x, ["?x isOn y1"], BobSees),
    durability_names(myself, a, ["?a rdf:type oro:Agent"], Agents),
    test_bool(oro_check(myself, ["a2 isOn table1"]), A2),
    Got = [OnTable, BobSees, Agents, A2].

test(agent_model_is_known_again,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Seen == [x1])
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, ["bob rdf:type oro:Agent"]),
    oro_add(bob, ["x1 isOn y1"]),
    oro_init([db(Dir), commonsense(false)]),
    durability_names(bob, x, ["?x isOn ?y"], Seen).

test(removed_ontology_triple_stays_removed,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Before-After == true-false)
     ]) :-
    oro_init([db(Dir)]),
    test_bool(oro_check(myself, ["Robot rdfs:subClassOf EmbodiedAgent"]), Before),
    oro_remove(myself, ["Robot rdfs:subClassOf EmbodiedAgent"]),
    oro_init([db(Dir)]),
    test_bool(oro_check(myself, ["Robot rdfs:subClassOf EmbodiedAgent"]), After).

test(ontology_not_journaled,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Ontology == [])
     ]) :-
    oro_init([db(Dir)]),
    oro_add(myself, ["k1 isOn t1"]),
    findall(G, ( rdf_graph(G),
                 sub_atom(G, 0, _, _, 'oro:ontology'),
                 rdf_journal_file(G, _)
               ), Ontology).

test(reset_is_durable,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(After == false)
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, ["k1 isOn t1"]),
    oro_reset,
    oro_init([db(Dir), commonsense(false)]),
    test_bool(oro_check(myself, ["k1 isOn t1"]), After).

test(saved_file_not_journaled,
     [ setup(( durability_dir(Dir), tmp_file(oro_save, SaveDir),
               make_directory(SaveDir) )),
       cleanup(( durability_cleanup(Dir),
                 delete_directory_and_contents(SaveDir) )),
       true(Journals == [])
     ]) :-
    oro_init([db(Dir), commonsense(false), save_dir(SaveDir)]),
    oro_add(myself, ["k1 isOn t1"]),
    oro_save(myself, 'out.owl'),
    findall(J, rdf_journal_file('oro:save', J), Journals).

:- end_tests(durability_restore).

:- begin_tests(durability_memory).

%   With a long time unit the deadline is the same after the restart.

test(deadline_kept,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(After == Before)
     ]) :-
    oro_init([db(Dir), commonsense(false), time_base(100000)]),
    oro_add(myself, ["s1 isOn table1"], shortterm),
    oro_memory_deadlines(myself, Before),
    Before = [_],
    oro_init([db(Dir), commonsense(false), time_base(100000)]),
    oro_memory_deadlines(myself, After).

%   A fact whose deadline passed while the server was down is gone at
%   start; a long-term one stays.

test(expired_gone_at_start,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Got == false-true-[])
     ]) :-
    oro_init([db(Dir), commonsense(false), time_base(20)]),
    oro_add(myself, ["s1 isOn table1"], shortterm),
    oro_add(myself, ["l1 isOn table1"]),
    oro_memory_deadlines(myself, [Deadline-_-_]),
    oro_close,
    %   Whether or not this process forgot it meanwhile (that change is
    %   not journaled any more), the restored store must not have it.
    durability_wait_past(Deadline, 60),
    oro_init([db(Dir), commonsense(false), time_base(20)]),
    test_bool(oro_check(myself, ["s1 isOn table1"]), S1),
    test_bool(oro_check(myself, ["l1 isOn table1"]), L1),
    oro_memory_deadlines(myself, Left),
    Got = S1-L1-Left.

%   The deadline of a restored fact is never earlier than recorded.

durability_wait_past(DeadlineMs, MaxSeconds) :-
    assertion(test_wait_until(durability_past(DeadlineMs), MaxSeconds)).

durability_past(DeadlineMs) :-
    get_time(Now),
    Now * 1000 > DeadlineMs.

:- end_tests(durability_memory).

:- begin_tests(durability_repair).

%   A change that was written to a journal but whose commit line is
%   missing (the crash came before it) is dropped whole, and so is a
%   last journal line cut in two.

test(uncommitted_change_dropped,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Got == true-false-false)
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, ["k1 isOn t1"]),
    oro_add(myself, ["k2 isOn t1", "k3 isOn t1"]),
    oro_close,
    directory_file_path(Dir, 'oro.jnl', Log),
    durability_drop_last_commit(Log),
    oro_init([db(Dir), commonsense(false)]),
    test_bool(oro_check(myself, ["k1 isOn t1"]), K1),
    test_bool(oro_check(myself, ["k2 isOn t1"]), K2),
    test_bool(oro_check(myself, ["k3 isOn t1"]), K3),
    Got = K1-K2-K3.

test(cut_line_dropped,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Got == true-false)
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, ["k1 isOn t1"]),
    oro_add(myself, ["k2 isOn t1"]),
    oro_close,
    once(directory_member(Dir, Journal,
                          [recursive(true), extensions([jrn])])),
    durability_cut_before_end(Journal),
    oro_init([db(Dir), commonsense(false)]),
    test_bool(oro_check(myself, ["k1 isOn t1"]), K1),
    test_bool(oro_check(myself, ["k2 isOn t1"]), K2),
    Got = K1-K2.

%   Remove the last `commit(N).` line of the commit log.

durability_drop_last_commit(Log) :-
    read_file_to_string(Log, Text, []),
    split_string(Text, "\n", "", Lines0),
    exclude(==(""), Lines0, Lines1),
    once(append(Keep, [Last], Lines1)),
    assertion(sub_string(Last, 0, _, _, "commit(")),
    setup_call_cleanup(open(Log, write, Out),
                       forall(member(L, Keep), format(Out, "~s~n", [L])),
                       close(Out)).

%   Cut the journal in the middle of its last `assert(` line (the
%   change's end line and what follows are lost, as in a crash).

durability_cut_before_end(Journal) :-
    read_file_to_string(Journal, Text, []),
    once(( sub_string(Text, B, _, _, "assert("),
           \+ ( sub_string(Text, B2, _, _, "assert("), B2 > B ) )),
    Cut is B + 20,
    sub_string(Text, 0, Cut, _, Kept),
    setup_call_cleanup(open(Journal, write, Out),
                       write(Out, Kept),
                       close(Out)).

:- end_tests(durability_repair).

:- begin_tests(durability_compaction).

test(steady_updates_stay_small,
     [ setup(( durability_dir(Dir),
               setting(oro_persist:compact_every, E),
               setting(oro_persist:journal_min_kb, K),
               set_setting(oro_persist:compact_every, 100),
               set_setting(oro_persist:journal_min_kb, 8) )),
       cleanup(( set_setting(oro_persist:compact_every, E),
                 set_setting(oro_persist:journal_min_kb, K),
                 durability_cleanup(Dir) )),
       true(Got == true-true)
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, ["hasBattery rdf:type owl:FunctionalProperty"]),
    forall(between(1, 3000, I),
           ( format(string(S), "robot1 hasBattery ~d", [I]),
             oro_update(myself, [S])
           )),
    oro_persist_sizes(Sizes),
    Small = Sizes.total,
    format(user_error, "~n% 3000 updates: ~p~n", [Sizes]),
    test_bool(Small < 64 * 1024, SmallEnough),
    oro_init([db(Dir), commonsense(false)]),
    test_bool(oro_check(myself, ["robot1 hasBattery 3000"]), Last),
    Got = SmallEnough-Last.

:- end_tests(durability_compaction).

		 /*******************************
		 *     THE REAL SERVER, KILLED  *
		 *******************************/

%   durability_server(+Dir, -Pid, -Port, -Out): start the real server
%   on a free port with --db=Dir (no common-sense ontology: faster).

durability_server(Dir, Pid, Port, Out) :-
    test_checkout_path('server/oro_server.pl', Server),
    atom_concat('--db=', Dir, DbOption),
    process_create(path(swipl),
                   [Server, '--port=0', '--no-commonsense', DbOption],
                   [ stdout(pipe(Out)), stderr(null), process(Pid) ]),
    read_line_to_string(Out, Line),
    (   split_string(Line, ":", " ", Parts),
        last(Parts, PortText),
        number_string(Port, PortText)
    ->  true
    ;   process_kill(Pid, kill),
        process_wait(Pid, _),
        throw(error(existence_error(server_line, Line), _))
    ).

durability_kill(Pid, Out) :-
    catch(process_kill(Pid, kill), _, true),
    process_wait(Pid, _, [timeout(30)]),
    close(Out).

durability_kills(N) :-
    (   getenv('ORO_LONG_TESTS', '1')
    ->  N = 50
    ;   N = 5
    ).

%   One round: send batches (of 1 to 200 statements, each statement
%   naming its batch), each acknowledged one recorded, send one more
%   without waiting, then kill -9 the server after a random short
%   delay.  Returns the acknowledged batches and the one in flight.

durability_round(Dir, Round, Acked, InFlight) :-
    durability_server(Dir, Pid, Port, Out),
    random_between(3, 25, Count),
    call_cleanup(
        ( oro_connect(Port, Conn),
          call_cleanup(durability_batches(Conn, Round, Count, Acked, InFlight),
                       oro_disconnect(Conn))
        ),
        durability_kill(Pid, Out)).

durability_batches(Conn, Round, Count, Acked, InFlight) :-
    findall(B, between(1, Count, B), Bs),
    foldl(durability_batch(Conn, Round), Bs, [], Acked0),
    reverse(Acked0, Acked),
    Next is Count + 1,
    durability_batch_request(Round, Next, Size, Params),
    oro_send(Conn, add, Params),
    InFlight = batch(Round, Next, Size),
    random_between(0, 4, Ms),
    Delay is Ms / 1000,
    sleep(Delay).

durability_batch(Conn, Round, B, Acked0, Acked) :-
    durability_batch_request(Round, B, Size, Params),
    oro_call(Conn, add, Params, Reply),
    (   Reply = ok(_)
    ->  Acked = [batch(Round, B, Size)|Acked0]
    ;   Acked = Acked0
    ).

durability_batch_request(Round, B, Size, [Set]) :-
    random_between(1, 200, Size),
    numlist(1, Size, Is),
    maplist(durability_statement(Round, B), Is, Statements),
    atomic_list_concat(Statements, ', ', Body),
    format(string(Set), "[~w]", [Body]).

durability_statement(Round, B, I, S) :-
    format(string(S), "d_~d_~d_~d crashTest v_~d_~d", [Round, B, I, Round, B]).

%   The statements found after the restart, as Round-Batch-Count.

durability_found(Port, Found) :-
    oro_connect(Port, Conn),
    call_cleanup(oro_call(Conn, find, ["x", "[?x crashTest ?v]"], Reply),
                 oro_disconnect(Conn)),
    Reply = ok(Line),
    test_json(Line, Names),
    findall(R-B, ( member(N, Names),
                   split_string(N, "_", "", ["d", RT, BT, _]),
                   number_string(R, RT),
                   number_string(B, BT)
                 ), Keys0),
    msort(Keys0, Keys),
    clumped(Keys, Found).

:- begin_tests(durability_kill9).

test(no_acknowledged_statement_lost, [true(Problems == [])]) :-
    durability_dir(Dir),
    durability_kills(Kills),
    set_random(seed(2026)),
    call_cleanup(
        ( numlist(1, Kills, Rounds),
          foldl(durability_round_acc(Dir), Rounds, []-[], Acked-InFlight),
          durability_server(Dir, Pid, Port, Out),
          call_cleanup(durability_found(Port, Found),
                       durability_kill(Pid, Out)),
          durability_problems(Acked, InFlight, Found, Problems),
          length(Acked, NAcked),
          aggregate_all(sum(S), member(batch(_, _, S), Acked), NStatements),
          length(Problems, NProblems),
          format(user_error, "~n% kill -9: ~d kills, ~d acknowledged batches \c
                              (~d statements), ~d lost or partial~n",
                 [Kills, NAcked, NStatements, NProblems])
        ),
        delete_directory_and_contents(Dir)).

durability_round_acc(Dir, Round, Acked0-Flight0, Acked-Flight) :-
    durability_round(Dir, Round, A, F),
    append(Acked0, A, Acked),
    Flight = [F|Flight0].

%   Problems: an acknowledged batch missing or incomplete, a batch
%   neither acknowledged nor in flight, a batch in flight present in
%   part.

durability_problems(Acked, InFlight, Found, Problems) :-
    findall(missing(R, B, Size, Have),
            ( member(batch(R, B, Size), Acked),
              (   memberchk((R-B)-Have, Found)
              ->  Have =\= Size
              ;   Have = 0
              )
            ), Missing),
    findall(partial(R, B, Size, Have),
            ( member(batch(R, B, Size), InFlight),
              memberchk((R-B)-Have, Found),
              Have =\= Size
            ), Partial),
    findall(unknown(R, B),
            ( member((R-B)-_, Found),
              \+ memberchk(batch(R, B, _), Acked),
              \+ memberchk(batch(R, B, _), InFlight)
            ), Unknown),
    append([Missing, Partial, Unknown], Problems).

:- end_tests(durability_kill9).

:- begin_tests(durability_sigterm).

test(sigterm_exits_cleanly, [true(Got == exit(0)-ok("true"))]) :-
    durability_dir(Dir),
    call_cleanup(
        ( durability_server(Dir, Pid, Port, Out),
          oro_connect(Port, Conn),
          oro_call(Conn, add, ["[k1 isOn t1]"], _),
          oro_disconnect(Conn),
          process_kill(Pid, term),
          process_wait(Pid, Status, [timeout(30)]),
          close(Out),
          durability_server(Dir, Pid2, Port2, Out2),
          call_cleanup(( oro_connect(Port2, Conn2),
                         oro_call(Conn2, check, ["[k1 isOn t1]"], Reply),
                         oro_disconnect(Conn2)
                       ),
                       durability_kill(Pid2, Out2)),
          Got = Status-Reply
        ),
        delete_directory_and_contents(Dir)).

:- end_tests(durability_sigterm).
