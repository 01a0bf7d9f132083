:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(oro_test_client).
:- use_module('../bench/bench_common', [bench_pin_to_cpu/1, bench_cpus/1, bench_set_cpus/1]).
:- use_module(library(oro)).
:- use_module(library(oro/reason/oro_reason),
              [oro_compiled_schema/2, oro_schema_superclass/3]).

/*  Tests for durability (issue #8): the database directory of
    oro_init/1's db(Dir) and the server's --db=DIR.

      - what a model holds, agents and masked ontology triples
        included, comes back after a restart; the ontology layer is not
        journaled;
      - short-term and episodic facts keep their deadlines across a
        restart, and those past their deadline are gone at start;
      - a journal cut by a crash (a line cut in two, a change not
        committed) is repaired: a change comes back whole or not at all;
        so is a kill inside a compaction (a snapshot or the commit log
        being rewritten), and the server starts on what is left;
      - kill -9 of the real server at random moments loses no
        acknowledged statement and never a part of a batch (5 kills by
        default, 50 with ORO_LONG_TESTS=1); the same against a server
        that compacts its journals every few changes, with removes,
        updates and adds to an agent's model;
      - SIGTERM and SIGINT stop the server cleanly (exit 0, everything
        kept); a request in progress when SIGTERM comes is finished and
        answered, and no new connection is accepted meanwhile;
      - journals are compacted under a stream of updates, and a store
        that grew and shrank in large changes keeps on disk a constant
        times its live triples;
      - library(semweb/rdf_persistency) is loaded only when a database
        directory is given (it is 15 ms of a server's start).

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
:- use_module(library(pairs)).
:- use_module(library(socket)).
:- use_module(library(oro/oro_persist)).
:- use_module(library(oro/oro_store),
              [oro_shared_graph/2, oro_store_attach/1, oro_store_detach/0]).

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

%   This process has loaded rdf_persistency: the fixture runs in a
%   child process.

:- begin_tests(durability_loaded_on_use).

test(persistency_with_a_directory_only,
     true(Got == persistency(absent, loaded))) :-
    test_child_term('test/fixtures/persistency_on_use.pl', Got).

:- end_tests(durability_loaded_on_use).

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

%   An agent named by a long IRI: its journals' names would be over
%   the 255 bytes a file name may have; the facts must come back all
%   the same, also from a compacted commit log.

test(long_agent_name_comes_back,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Seen-Digests == [[x1], [x1], [x2]]-[])
     ]) :-
    durability_long_agents(Long, Accented),
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, [rdf(Long, rdf:type, oro:'Agent'),
                     rdf(Accented, rdf:type, oro:'Agent')]),
    oro_add(Long, ["x1 isOn y1"]),
    oro_add(Accented, ["x2 isOn y1"]),
    oro_init([db(Dir), commonsense(false)]),
    durability_names(Long, x, ["?x isOn y1"], Seen1),
    oro_persist_compact,
    oro_init([db(Dir), commonsense(false)]),
    durability_names(Long, x, ["?x isOn y1"], Seen2),
    durability_names(Accented, x, ["?x isOn y1"], Seen3),
    Seen = [Seen1, Seen2, Seen3],
    % No model named by a digest: each is known by its name again.
    oro_agents(Models),
    include([M]>>sub_atom(M, 0, 1, _, ~), Models, Digests).

durability_long_agents(Long, Accented) :-
    length(As, 300),
    maplist(=(0'a), As),
    atom_codes(A300, As),
    atom_concat('http://example.org/robots/', A300, Long),
    length(Es, 40),
    maplist(=(0'\u00e9), Es),
    atom_codes(E40, Es),
    atom_concat('http://example.org/', E40, Accented).

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
    oro_shared_graph(scratch(save), Graph),
    findall(J, rdf_journal_file(Graph, J), Journals).

%   Attaching a database restores its models' schema triples: the
%   watcher thread compiles the new tables ahead, before any query.

test(restored_schema_compiled_ahead,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Key1 \== Key0)
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, ["Gadget rdfs:subClassOf Artifact"]),
    oro_store_detach,
    oro_reset,                              % not journaled: detached
    durability_compiled(Key0),
    rdf_global_id(oro:'Gadget', Gadget),
    rdf_global_id(oro:'Artifact', Artifact),
    assertion(\+ oro_schema_superclass(Key0, Gadget, Artifact)),
    oro_store_attach(Dir),
    durability_compiled(Key1),
    assertion(oro_schema_superclass(Key1, Gadget, Artifact)).

:- end_tests(durability_restore).

%   durability_compiled(-Key): myself's shared schema tables for the
%   current generation, once the watcher thread has compiled them (10 s
%   at most).

durability_compiled(Key) :-
    assertion(test_wait_until(oro_compiled_schema(myself, _), 10)),
    oro_compiled_schema(myself, Key).

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

test(episodic_deadline_kept,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(After == Before)
     ]) :-
    oro_init([db(Dir), commonsense(false), time_base(100000)]),
    oro_add(myself, ["e1 isOn table1"], episodic),
    oro_memory_deadlines(myself, Before),
    Before = [_-_-episodic],
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

%   Kills during a compaction, at each point where the files on disk
%   change.  rdf_persistency compacts a graph by writing Graph.trp.new,
%   deleting the journal (which lives in another directory level than
%   the snapshot: both are placed by a hash of their file name), then
%   renaming Graph.trp.new to Graph.trp; the commit log is rewritten as
%   oro.jnl.new, then renamed.  Each state is made by hand from the real
%   files, so every crash point is tested on each run (a kill -9 at
%   random rarely lands inside a compaction), and the real server is
%   started on it: a snapshot rdf_db cannot read aborts the process.

%   Killed while writing the snapshot: the journal still holds every
%   change and the partial snapshot is dropped.

test(killed_writing_snapshot,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Got == [ok("true"), ok("true")]-[])
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, ["k1 isOn t1"]),
    durability_compact,
    oro_add(myself, ["k2 isOn t1"]),
    oro_close,
    findall(S, durability_file(Dir, trp, S), Snapshots),
    assertion(Snapshots \== []),
    forall(member(S, Snapshots),
           ( assertion(durability_journal(Dir, S, _)),
             file_name_extension(S, new, New),
             durability_copy_half(S, New)
           )),
    durability_restart_check(Dir, ["[k1 isOn t1]", "[k2 isOn t1]"], Replies),
    findall(N, durability_file(Dir, new, N), Left),
    Got = Replies-Left.

%   Killed after the journal was deleted, before the rename: the new
%   snapshot is complete and replaces the old one.

test(killed_before_snapshot_rename,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Got == [ok("true"), ok("true")]-[])
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, ["k1 isOn t1"]),
    durability_compact,
    findall(S-Old, ( durability_file(Dir, trp, S),
                     read_file_to_codes(S, Old, [type(binary)])
                   ), Olds),
    assertion(Olds \== []),
    oro_add(myself, ["k2 isOn t1"]),
    durability_compact,
    oro_close,
    forall(member(S-Old, Olds),
           ( file_name_extension(S, new, New),
             rename_file(S, New),
             durability_write_codes(S, Old),
             forall(durability_journal(Dir, S, Journal),
                    delete_file(Journal))
           )),
    durability_restart_check(Dir, ["[k1 isOn t1]", "[k2 isOn t1]"], Replies),
    findall(N, durability_file(Dir, new, N), Left),
    Got = Replies-Left.

%   Killed while rewriting the commit log: the old one is intact (the
%   new one is renamed over it only once written), so the server starts
%   with everything.

test(killed_rewriting_commit_log,
     [ setup(durability_dir(Dir)),
       cleanup(durability_cleanup(Dir)),
       true(Got == [ok("true"), ok("true")]-[])
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    oro_add(myself, ["k1 isOn t1"]),
    oro_add(myself, ["k2 isOn t1"]),
    oro_close,
    directory_file_path(Dir, 'oro.jnl.new', New),
    setup_call_cleanup(open(New, write, Out),
                       format(Out, "commit(", []),
                       close(Out)),
    durability_restart_check(Dir, ["[k1 isOn t1]", "[k2 isOn t1]"], Replies),
    findall(N, durability_file(Dir, new, N), Left),
    Got = Replies-Left.

%   durability_compact: compact every journal now, as the store does
%   (under its write lock).

durability_compact :-
    with_mutex(oro_write, oro_persist_compact).

%   durability_file(+Dir, +Ext, -File): a file of Dir (at any depth)
%   with extension Ext.

durability_file(Dir, Ext, File) :-
    directory_member(Dir, File, [recursive(true), extensions([Ext])]).

%   durability_journal(+Dir, +Snapshot, -Journal): the journal of the
%   graph of Snapshot, wherever its directory level puts it.

durability_journal(Dir, Snapshot, Journal) :-
    file_base_name(Snapshot, SnapshotBase),
    file_name_extension(Stem, trp, SnapshotBase),
    file_name_extension(Stem, jrn, JournalBase),
    durability_file(Dir, jrn, Journal),
    file_base_name(Journal, JournalBase).

durability_copy_half(From, To) :-
    read_file_to_codes(From, Codes, [type(binary)]),
    length(Codes, Len),
    Half is Len // 2,
    length(Prefix, Half),
    append(Prefix, _, Codes),
    durability_write_codes(To, Prefix).

durability_write_codes(File, Codes) :-
    setup_call_cleanup(open(File, write, Out, [type(binary)]),
                       format(Out, "~s", [Codes]),
                       close(Out)).

%   durability_restart_check(+Dir, +Sets, -Replies): start the real
%   server on Dir and check each of Sets; Replies is not_started(Error)
%   if it printed no listening line (it failed or aborted).

durability_restart_check(Dir, Sets, Replies) :-
    catch(durability_server(Dir, Pid, Port, Out), Error, true),
    (   var(Error)
    ->  call_cleanup(( oro_connect(Port, Conn),
                       call_cleanup(findall(Reply,
                                            ( member(Set, Sets),
                                              oro_call(Conn, check, [Set], Reply)
                                            ), Replies),
                                    oro_disconnect(Conn))
                     ),
                     durability_kill(Pid, Out))
    ;   Replies = not_started(Error)
    ).

:- end_tests(durability_repair).

:- begin_tests(durability_compaction).

%   durability_compacting(-Dir, +Every, +MinKB, -Saved): a fresh
%   directory name, with the compaction settings compact_every and
%   journal_min_kb set to Every and MinKB; durability_compacted(+Dir,
%   +Saved) puts them back and removes the directory.

durability_compacting(Dir, Every, MinKB, saved(E, K)) :-
    durability_dir(Dir),
    setting(oro_persist:compact_every, E),
    setting(oro_persist:journal_min_kb, K),
    set_setting(oro_persist:compact_every, Every),
    set_setting(oro_persist:journal_min_kb, MinKB).

durability_compacted(Dir, saved(E, K)) :-
    set_setting(oro_persist:compact_every, E),
    set_setting(oro_persist:journal_min_kb, K),
    durability_cleanup(Dir).

test(steady_updates_stay_small,
     [ setup(durability_compacting(Dir, 100, 8, Saved)),
       cleanup(durability_compacted(Dir, Saved)),
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

%   A store that grew and shrank, in large changes: 5,000 triples added
%   in 5 changes, 4,900 of them removed in 49.  What is on disk (and
%   what a restart reads) stays within a constant of the 100 live
%   triples: compaction is checked by the triples changed, not the
%   changes, and a journal outweighing a fraction of its snapshot
%   replaces a snapshot of what the store held at its largest.  Each
%   triple weighs about 50 bytes in a snapshot, 80 in a journal.

test(shrunk_store_stays_small,
     [ setup(durability_compacting(Dir, 100, 1, Saved)),
       cleanup(durability_compacted(Dir, Saved)),
       true(Got == true-[true, false]-100)
     ]) :-
    oro_init([db(Dir), commonsense(false)]),
    forall(between(0, 4, B),
           ( findall(S, ( between(1, 1000, I),
                          N is B * 1000 + I,
                          format(string(S), "shrunk_~d isOn t1", [N])
                        ), Adds),
             oro_add(myself, Adds)
           )),
    forall(between(0, 48, B),
           ( findall(S, ( between(1, 100, I),
                          N is 100 + B * 100 + I,
                          format(string(S), "shrunk_~d isOn t1", [N])
                        ), Removes),
             oro_remove(myself, Removes)
           )),
    oro_persist_sizes(Sizes),
    format(user_error, "~n% 100 live triples left by 54 changes: ~p~n", [Sizes]),
    test_bool(Sizes.total < 32 * 1024, Small),
    oro_init([db(Dir), commonsense(false)]),
    test_bool(oro_check(myself, ["shrunk_100 isOn t1"]), Kept),
    test_bool(oro_check(myself, ["shrunk_101 isOn t1"]), Removed),
    test_find(myself, x, ["?x isOn t1"], Live),
    length(Live, NLive),
    Got = Small-[Kept, Removed]-NLive.

:- end_tests(durability_compaction).

		 /*******************************
		 *     THE REAL SERVER, KILLED  *
		 *******************************/

%   durability_server(+Dir, -Pid, -Port, -Out): start the real server
%   on a free port with --db=Dir (no common-sense ontology: faster).
%
%   durability_server(+Dir, +Goals, +Options, -Pid, -Port, -Out): the
%   same with the command-line Options instead of --no-commonsense, and
%   Goals (atoms) given to swipl as `-g Goal` before the script: swipl
%   runs them after loading server/oro_server.pl and before its
%   main/0, so they can change the server's settings without any new
%   option of the server.

durability_server(Dir, Pid, Port, Out) :-
    durability_server(Dir, [], ['--no-commonsense'], Pid, Port, Out).

durability_server(Dir, Goals, Options, Pid, Port, Out) :-
    atom_concat('--db=', Dir, DbOption),
    durability_server_args(Goals, [DbOption|Options], Args),
    process_create(path(swipl), Args,
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

%   durability_server_args(+Goals, +Options, -Args): swipl's arguments
%   for a server on a free port that runs Goals (-g) first.

durability_server_args(Goals, Options, Args) :-
    test_checkout_path('server/oro_server.pl', Server),
    findall(Arg, ( member(Goal, Goals),
                   member(Arg, ['-g', Goal])
                 ), GoalArgs),
    append([GoalArgs, [Server, '--port=0', '--no-http'], Options], Args).

durability_kill(Pid, Out) :-
    catch(process_kill(Pid, kill), _, true),
    test_process_wait(Pid, _, 30),
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
    test_set_text(Statements, Set).

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

		 /*******************************
		 *   KILLED WHILE COMPACTING    *
		 *******************************/

%   The same kill -9 rounds against a server that compacts all the
%   time: it checks every 20 triples changed (oro_persist:compact_every)
%   and compacts each journal past 1 KB (journal_min_kb) that outweighs
%   a quarter of its snapshot (journal_ratio), so snapshots are written
%   and the commit log is
%   rewritten all through the rounds, and kills land before, during
%   and after compactions.  The traffic mixes adds, removes of
%   acknowledged statements, updates of a functional property and
%   adds to the model of an agent (gerard, made an agent by `gerard
%   rdf:type Human` through the common-sense ontology).

durability_compacting_server(Dir, Pid, Port, Out) :-
    durability_server(Dir,
                      [ 'set_setting(oro_persist:compact_every, 20)',
                        'set_setting(oro_persist:journal_min_kb, 1)'
                      ],
                      [], Pid, Port, Out).

%   durability_compact_round(+Dir, +Round, +Log0, -Log): one round;
%   Log (newest first) adds op(Status, Op) for each operation sent,
%   Status being `acked`, refused(Reply) or `in_flight` (the last one,
%   whose reply was not awaited).  Op is add(Model, Round, Step, Size),
%   remove(Round, Step) (the first statement of that acknowledged add
%   to myself) or update(N).

durability_compact_round(Dir, Round, Log0, Log) :-
    durability_compacting_server(Dir, Pid, Port, Out),
    random_between(5, 25, Count),
    call_cleanup(
        ( oro_connect(Port, Conn),
          call_cleanup(durability_ops(Conn, Round, Count, Log0, Log),
                       oro_disconnect(Conn))
        ),
        durability_kill(Pid, Out)).

durability_ops(Conn, Round, Count, Log0, Log) :-
    (   Round =:= 1
    ->  Setup = "[crashLevel rdf:type owl:FunctionalProperty, gerard rdf:type Human]",
        oro_call(Conn, add, [Setup], Reply),
        test_expect_ok(add-[Setup], Reply, _)
    ;   true
    ),
    numlist(1, Count, Steps),
    foldl(durability_op(Conn, Round), Steps, Log0, Log1),
    Next is Count + 1,
    durability_pick_op(Log1, Round, Next, Op),
    durability_op_request(Op, Method, Params),
    oro_send(Conn, Method, Params),
    Log = [op(in_flight, Op)|Log1],
    random_between(0, 4, Ms),
    Delay is Ms / 1000,
    sleep(Delay).

durability_op(Conn, Round, Step, Log0, [op(Status, Op)|Log0]) :-
    durability_pick_op(Log0, Round, Step, Op),
    durability_op_request(Op, Method, Params),
    oro_call(Conn, Method, Params, Reply),
    (   Reply = ok(_)
    ->  Status = acked
    ;   Status = refused(Reply)
    ).

%   durability_pick_op(+Log, +Round, +Step, -Op): 40% add to myself,
%   25% add to gerard, 15% remove (if an acknowledged add to myself is
%   left whose first statement no remove was sent for), else update.

durability_pick_op(Log, Round, Step, Op) :-
    random_between(1, 100, X),
    findall(R-S, ( member(op(acked, add(myself, R, S, _)), Log),
                   \+ memberchk(op(_, remove(R, S)), Log)
                 ), Removable),
    (   X =< 40
    ->  random_between(1, 200, Size),
        Op = add(myself, Round, Step, Size)
    ;   X =< 65
    ->  random_between(1, 200, Size),
        Op = add(gerard, Round, Step, Size)
    ;   X =< 80,
        Removable \== []
    ->  random_member(R-S, Removable),
        Op = remove(R, S)
    ;   N is Round * 1000 + Step,
        Op = update(N)
    ).

durability_op_request(add(myself, R, S, Size), add, [Set]) :-
    durability_op_set(c, R, S, 1, Size, Set).
durability_op_request(add(gerard, R, S, Size), addForAgent, ["gerard", Set]) :-
    durability_op_set(g, R, S, 1, Size, Set).
durability_op_request(remove(R, S), remove, [Set]) :-
    durability_op_set(c, R, S, 1, 1, Set).
durability_op_request(update(N), update, [Set]) :-
    format(string(Set), "[robot1 crashLevel ~d]", [N]).

%   Statements Prefix_R_S_I crashTest v_R_S, I in From..To.

durability_op_set(Prefix, R, S, From, To, Set) :-
    numlist(From, To, Is),
    maplist(durability_op_statement(Prefix, R, S), Is, Statements),
    test_set_text(Statements, Set).

durability_op_statement(Prefix, R, S, I, Statement) :-
    format(string(Statement), "~w_~d_~d_~d crashTest v_~d_~d",
           [Prefix, R, S, I, R, S]).

%   durability_compact_found(+Port, -Found, -Levels): Found are the
%   (Model-Round-Step)-Is of the crashTest statements of myself and
%   gerard, Is sorted; Levels the values of robot1 crashLevel.  Found
%   is agent_lost(Reply) if gerard's model cannot be queried.

durability_compact_found(Port, Found, Levels) :-
    oro_connect(Port, Conn),
    call_cleanup(( oro_call(Conn, find, ["x", "[?x crashTest ?v]"], Mine),
                   oro_call(Conn, findForAgent,
                            ["gerard", "x", "[?x crashTest ?v]"], His),
                   oro_call(Conn, find, ["v", "[robot1 crashLevel ?v]"], Level)
                 ),
                 oro_disconnect(Conn)),
    Mine = ok(MineLine),
    test_json(MineLine, MyNames),
    Level = ok(LevelLine),
    test_json(LevelLine, Levels0),
    maplist(durability_number, Levels0, Levels),
    (   His = ok(HisLine)
    ->  test_json(HisLine, HisNames),
        findall(Key-I, ( member(N, MyNames),
                         durability_op_key(N, "c", myself, Key, I)
                       ; member(N, HisNames),
                         durability_op_key(N, "g", gerard, Key, I)
                       ), Pairs0),
        msort(Pairs0, Pairs),
        group_pairs_by_key(Pairs, Found)
    ;   Found = agent_lost(His)
    ).

durability_op_key(Name, Prefix, Model, Model-R-S, I) :-
    split_string(Name, "_", "", [Prefix, RT, ST, IT]),
    number_string(R, RT),
    number_string(S, ST),
    number_string(I, IT).

durability_number(Value, Number) :-
    (   number(Value)
    ->  Number = Value
    ;   number_string(Number, Value)
    ).

%   durability_compact_problems(+Log, +Found, +Levels, -Problems)
%
%   An acknowledged add must be there whole (less its first statement
%   if a remove of it was acknowledged; with or without it if that
%   remove was in flight); an add in flight whole or not at all;
%   nothing else may be there; no operation may be refused; robot1 has
%   one crashLevel, the last acknowledged update's or that of an update
%   in flight after it.

durability_compact_problems(_, agent_lost(Reply), _, [agent_lost(Reply)]) :-
    !.
durability_compact_problems(Log, Found, Levels, Problems) :-
    findall(missing(Key, Size, Have),
            ( member(op(acked, add(M, R, S, Size)), Log),
              Key = M-R-S,
              durability_have(Key, Found, Have),
              numlist(1, Size, All),
              numlist(2, Size, Rest),
              (   M == gerard
              ->  Allowed = [All]
              ;   memberchk(op(acked, remove(R, S)), Log)
              ->  Allowed = [Rest]
              ;   memberchk(op(in_flight, remove(R, S)), Log)
              ->  Allowed = [All, Rest]
              ;   Allowed = [All]
              ),
              \+ memberchk(Have, Allowed)
            ), Missing),
    findall(partial(Key, Size, Have),
            ( member(op(in_flight, add(M, R, S, Size)), Log),
              Key = M-R-S,
              durability_have(Key, Found, Have),
              numlist(1, Size, All),
              \+ memberchk(Have, [[], All])
            ), Partial),
    findall(unknown(M-R-S),
            ( member((M-R-S)-_, Found),
              \+ ( member(op(Status, add(M, R, S, _)), Log),
                   memberchk(Status, [acked, in_flight])
                 )
            ), Unknown),
    findall(refused(Op, Reply), member(op(refused(Reply), Op), Log), Refused),
    reverse(Log, Oldest),
    foldl(durability_level_allowed, Oldest, [none], AllowedLevels),
    (   Levels == []
    ->  Level = none
    ;   Levels = [Level0]
    ->  Level = Level0
    ;   Level = Levels
    ),
    (   memberchk(Level, AllowedLevels)
    ->  LevelProblems = []
    ;   LevelProblems = [level(Levels, AllowedLevels)]
    ),
    append([Missing, Partial, Unknown, Refused, LevelProblems], Problems).

durability_have(Key, Found, Have) :-
    (   memberchk(Key-Have0, Found)
    ->  Have = Have0
    ;   Have = []
    ).

durability_level_allowed(op(acked, update(N)), _, [N]) :-
    !.
durability_level_allowed(op(in_flight, update(N)), Allowed, [N|Allowed]) :-
    !.
durability_level_allowed(_, Allowed, Allowed).

:- begin_tests(durability_kill9_compaction).

test(no_acknowledged_change_lost_compacting, [true(Problems == [])]) :-
    durability_dir(Dir),
    durability_kills(Kills),
    set_random(seed(2027)),
    call_cleanup(
        ( numlist(1, Kills, Rounds),
          foldl(durability_compact_round(Dir), Rounds, [], Log),
          findall(F, directory_member(Dir, F, [ recursive(true),
                                                extensions([trp])
                                              ]), Snapshots),
          length(Snapshots, NSnapshots),
          durability_compacting_server(Dir, Pid, Port, Out),
          call_cleanup(durability_compact_found(Port, Found, Levels),
                       durability_kill(Pid, Out)),
          durability_compact_problems(Log, Found, Levels, Problems0),
          (   NSnapshots =:= 0
          ->  Problems = [no_compaction|Problems0]
          ;   Problems = Problems0
          ),
          aggregate_all(count, member(op(acked, _), Log), NAcked),
          aggregate_all(sum(Size), member(op(acked, add(_, _, _, Size)), Log),
                        NStatements),
          length(Problems, NProblems),
          format(user_error, "~n% kill -9 while compacting: ~d kills, ~d \c
                              acknowledged operations (~d statements \c
                              added), ~d snapshot(s), ~d problem(s)~n",
                 [Kills, NAcked, NStatements, NSnapshots, NProblems])
        ),
        delete_directory_and_contents(Dir)).

:- end_tests(durability_kill9_compaction).

:- begin_tests(durability_sigterm).

test(sigterm_exits_cleanly, [true(Got == exit(0)-ok("true"))]) :-
    durability_signal_exit(term, Got).

test(sigint_exits_cleanly, [true(Got == exit(0)-ok("true"))]) :-
    durability_signal_exit(int, Got).

%   A SIGTERM sent as soon as the server says it listens stops it.  With
%   SWI-Prolog 9.0.4, a thread created but not run yet dropped a SIGTERM
%   the kernel handed it: before the server waited for its threads to
%   settle, 4 such stops in 60 were lost with the server and the sender
%   on one core, where the window is widest.  So this process and its
%   servers run on CPU 0 for the test when taskset(1) is there; each
%   server has 20 s to exit.

test(sigterm_right_after_listening, [true(Lost == [])]) :-
    durability_on_cpu0(findall(Round, ( between(1, 10, Round),
                                        \+ durability_quick_stop
                                      ),
                               Lost)).

durability_quick_stop :-
    durability_server_args([], ['--no-commonsense'], Args),
    process_create(path(swipl), Args,
                   [stdout(pipe(Out)), stderr(null), process(Pid)]),
    call_cleanup(
        ( read_line_to_string(Out, Line),
          sub_string(Line, 0, _, _, "oro listening"),
          process_kill(Pid, term),
          test_wait_until(\+ catch(process_wait(Pid, timeout, [timeout(0)]),
                                   _, fail),
                          20)
        ),
        durability_stopped(Pid, Out)).

%   durability_on_cpu0(:Goal): run Goal with every thread of this process
%   (and so the processes it starts) on CPU 0, if taskset(1) is there;
%   on the CPUs it had before afterwards.

:- meta_predicate durability_on_cpu0(0).

durability_on_cpu0(Goal) :-
    (   absolute_file_name(path(taskset), _, [access(execute),
                                               file_errors(fail)])
    ->  bench_cpus(CPUs),
        setup_call_cleanup(bench_pin_to_cpu(0),
                           once(Goal),
                           bench_set_cpus(CPUs))
    ;   once(Goal)
    ).

%   durability_signal_exit(+Signal, -Status-Reply): add a statement, send
%   Signal to the server, wait for its exit Status; Reply is the answer
%   to a check of the statement after a restart.

durability_signal_exit(Signal, Status-Reply) :-
    durability_dir(Dir),
    call_cleanup(
        ( durability_server(Dir, Pid, Port, Out),
          oro_connect(Port, Conn),
          oro_call(Conn, add, ["[k1 isOn t1]"], _),
          oro_disconnect(Conn),
          process_kill(Pid, Signal),
          durability_exit_status(Pid, Signal, Status),
          close(Out),
          durability_server(Dir, Pid2, Port2, Out2),
          call_cleanup(( oro_connect(Port2, Conn2),
                         oro_call(Conn2, check, ["[k1 isOn t1]"], Reply),
                         oro_disconnect(Conn2)
                       ),
                       durability_kill(Pid2, Out2))
        ),
        delete_directory_and_contents(Dir)).

%   A request in progress when SIGTERM arrives is finished and answered,
%   and its changes are kept; meanwhile the server accepts no new
%   connection.  So that the signal surely lands while the request runs,
%   whatever the machine's speed, the request is a method of a plugin
%   written by the test: it creates the file `started` (it then holds its
%   connection), waits for the file `go`, then adds a batch of 5,000
%   statements.  The test sends SIGTERM once `started` exists, waits
%   until connecting fails, creates `go`, and expects the `ok`, exit 0
%   and the whole batch after a restart.

test(sigterm_finishes_request_in_flight,
     [true(Got == ok("")-true-exit(0)-5000)]) :-
    durability_dir(Dir),
    tmp_file(oro_hold, Hold),
    make_directory(Hold),
    call_cleanup(durability_hold_run(Dir, Hold, 5000, Got),
                 ( delete_directory_and_contents(Hold),
                   (   exists_directory(Dir)
                   ->  delete_directory_and_contents(Dir)
                   ;   true
                   )
                 )).

durability_hold_run(Dir, Hold, Size, Reply-Refused-Status-Count) :-
    durability_hold_plugin(Hold, Plugin),
    atom_concat('--plugin=', Plugin, PluginOption),
    durability_server(Dir, [], ['--no-commonsense', PluginOption],
                      Pid, Port, Out),
    call_cleanup(durability_hold_request(Pid, Port, Hold, Size,
                                         Reply, Refused, Status),
                 durability_stopped(Pid, Out)),
    durability_count(Dir, "[?x heldBatch v]", Count).

durability_hold_request(Pid, Port, Hold, Size, Reply, Refused, Status) :-
    numlist(1, Size, Is),
    maplist(durability_held_statement, Is, Statements),
    test_set_text(Statements, Set),
    format(string(HoldParam), "\"~w\"", [Hold]),
    directory_file_path(Hold, started, Started),
    directory_file_path(Hold, go, Go),
    oro_connect(Port, Conn),
    call_cleanup(
        ( oro_send(Conn, durabilityHold, [HoldParam, Set]),
          assertion(test_wait_until(exists_file(Started), 30)),
          process_kill(Pid, term),
          test_bool(test_wait_until(durability_refused(Port), 30), Refused),
          setup_call_cleanup(open(Go, write, S), true, close(S)),
          oro_receive(Conn, Reply, 60),
          test_process_wait(Pid, Status, 60)
        ),
        oro_disconnect(Conn)).

durability_held_statement(I, S) :-
    format(string(S), "h_~d heldBatch v", [I]).

%   durability_refused(+Port): connecting to Port fails.

durability_refused(Port) :-
    catch(( tcp_connect('127.0.0.1':Port, Stream, []),
            close(Stream, [force(true)]),
            fail
          ),
          _, true).

%   durability_stopped(+Pid, +Out): the server has exited (and was
%   waited for), killed if it had not.

durability_stopped(Pid, Out) :-
    catch(process_wait(Pid, Status, [timeout(0)]), _, Status = waited),
    (   Status == timeout
    ->  durability_kill(Pid, Out)
    ;   close(Out)
    ).

%   durability_count(+Dir, +Pattern, -Count): how many ?x match Pattern
%   in the robot's model after a restart on Dir.

durability_count(Dir, Pattern, Count) :-
    durability_server(Dir, Pid, Port, Out),
    call_cleanup(( oro_connect(Port, Conn),
                   call_cleanup(oro_call(Conn, find, ["x", Pattern], Reply),
                                oro_disconnect(Conn))
                 ),
                 durability_kill(Pid, Out)),
    Reply = ok(Line),
    test_json(Line, Names),
    length(Names, Count).

%   durability_hold_plugin(+Hold, -File): write the plugin of
%   sigterm_finishes_request_in_flight into the directory Hold.

durability_hold_plugin(Hold, File) :-
    directory_file_path(Hold, 'durability_hold.pl', File),
    setup_call_cleanup(
        open(File, write, Out, [encoding(utf8)]),
        format(Out, "~s", [
":- module(durability_hold, []).
:- use_module(library(oro)).
:- use_module(library(filesex)).

oro_methods:method(durabilityHold(string, set), base,
                   \"Test only: wait for the file go, then add the statements.\",
                   hold).

hold(Dir, Statements, void) :-
    directory_file_path(Dir, started, Started),
    directory_file_path(Dir, go, Go),
    setup_call_cleanup(open(Started, write, S), true, close(S)),
    wait_for(Go, 6000),
    oro_add(myself, Statements).

wait_for(File, N) :-
    (   exists_file(File)
    ->  true
    ;   N > 0
    ->  sleep(0.01),
        N1 is N - 1,
        wait_for(File, N1)
    ;   throw(error(existence_error(file, File), _))
    ).
"]),
        close(Out)).

%   The request the brief's way: a large add, SIGTERM sent right after
%   it without waiting.  Whether the server had started the request
%   when the signal came depends on timing, so both outcomes are
%   accepted, but they must agree with the store: answered `ok` and the
%   whole batch kept, or not served (the connection closes) and nothing
%   of it kept.  The server exits 0 either way.

test(sigterm_reply_agrees_with_store,
     [true(Got == exit(0)-agree)]) :-
    durability_dir(Dir),
    call_cleanup(
        ( durability_server(Dir, Pid, Port, Out),
          call_cleanup(durability_add_then_term(Pid, Port, 5000, Reply, Status),
                       durability_stopped(Pid, Out)),
          durability_count(Dir, "[?x heldBatch v]", Count),
          (   Reply = ok(_),
              Count =:= 5000
          ->  Agree = agree,
              Outcome = "answered ok, batch kept"
          ;   Reply == end_of_file,
              Count =:= 0
          ->  Agree = agree,
              Outcome = "not served, batch absent"
          ;   Agree = disagree(Reply, Count),
              Outcome = "reply and store disagree"
          ),
          format(user_error, "~n% SIGTERM right after a 5,000-statement add: \c
                              ~s~n", [Outcome]),
          Got = Status-Agree
        ),
        delete_directory_and_contents(Dir)).

durability_add_then_term(Pid, Port, Size, Reply, Status) :-
    numlist(1, Size, Is),
    maplist(durability_held_statement, Is, Statements),
    test_set_text(Statements, Set),
    oro_connect(Port, Conn),
    call_cleanup(( oro_send(Conn, add, [Set]),
                   process_kill(Pid, term),
                   oro_receive(Conn, Reply, 60),
                   durability_exit_status(Pid, term, Status)
                 ),
                 oro_disconnect(Conn)).

%   durability_exit_status(+Pid, +Signal, -Status): the exit Status of
%   the server Pid, which was sent Signal (`timeout` if it runs 40 s
%   later).  SWI-Prolog 9.0.4 can lose a signal that the kernel gives to
%   a thread being created.  A connection's thread was one, when the
%   client sent the signal right after connecting (8 times in 200 runs
%   of sigterm_reply_agrees_with_store), until connections were served
%   by threads made at start (0 in 200).  The server still makes
%   threads at other times: one still running after 20 s is sent
%   Signal again, and the test says so.

durability_exit_status(Pid, Signal, Status) :-
    test_process_wait(Pid, Status0, 20),
    (   Status0 == timeout
    ->  format(user_error, "~n% The server did not act on ~w within 20 s: \c
                            sent again~n", [Signal]),
        process_kill(Pid, Signal),
        test_process_wait(Pid, Status, 20)
    ;   Status = Status0
    ).

:- end_tests(durability_sigterm).
