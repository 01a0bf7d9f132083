:- module(oro_persist,
          [ oro_persist_attach/1,       % +Directory
            oro_persist_detach/0,
            oro_persist_directory/1,    % -Directory
            oro_persist_transaction/2,  % +Action, :Goal
            oro_persist_record/1,       % +Record
            oro_persist_note/1,         % +Record
            oro_persist_records/1,      % -Records
            oro_persist_exclude/1,      % +Graph
            oro_persist_compact/0,
            oro_persist_sizes/1         % -Sizes
          ]).
:- use_module(library(semweb/rdf_db)).
:- autoload(library(semweb/rdf_persistency),
            [ rdf_attach_db/2, rdf_detach_db/0, rdf_flush_journals/1,
              rdf_journal_file/2, rdf_persistency/2, rdf_snapshot_file/2
            ]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(filesex)).
:- use_module(library(readutil)).
:- use_module(library(settings)).
:- use_module(library(debug)).

:- meta_predicate
    oro_persist_transaction(+, 0).

/** <module> Durability: journals that survive kill -9

With a database directory attached (`--db=DIR`, oro_init/1's db(Dir)),
every graph of the models is journaled by
library(semweb/rdf_persistency): each change appends to the journal of
each graph it touches, within the transaction that makes it, and the
journals are flushed before the change is reported done.  The ontology
layer and scratch graphs are excluded (oro_persist_exclude/1): they are
loaded again from their files.

rdf_persistency alone replays whatever lines a journal holds, so a
batch cut by a crash could come back in part, and a change spanning
several graphs could come back in some of them only.  This module adds
a commit log, `oro.jnl` in the same directory:

  - every change is an rdf_transaction/2 whose log message carries a
    sequence number, `log(oro(Seq, Action))`, so each journal brackets
    its part of the change with begin(..., oro(Seq, Action)) and end;
  - once the transaction is over (every journal flushed), `commit(Seq)`
    is appended to oro.jnl and flushed; only then does the caller reply;
  - records other modules attach to the change (oro_persist_record/1:
    the memory deadlines) are written just before its commit line, so
    they are committed with it or not at all.

On attach, before rdf_persistency reads anything, each journal is cut
before its first change that oro.jnl does not record as committed (a
crash can only leave the very last change incomplete, as writers are
serialised), a line cut in the middle included, and an interrupted
compaction is finished or undone.  A change is thus recovered whole or
not at all, and every change whose `ok` reached a client is recovered.

Journals are compacted (rdf_flush_journals/1: a snapshot of the live
triples replaces the journal) when they outgrow both `journal_min_kb`
and `journal_ratio` times their snapshot, checked each time
`compact_every` triples have changed (a monitor counts them, whatever
the size of the changes); oro.jnl is rewritten with the records still
live at the same time.  So the directory holds a snapshot of at most
about the live triples and a journal of a fraction of them, whatever
the history: a steady stream of updates to a few facts keeps it small,
a store that grew and then shrank is compacted to its new size, and a
restart reads time in proportion to the live triples, not to every
change ever made.  A restart checks the journals at its first change.
*/

:- setting(compact_every, positive_integer, 1000,
           'Triples changed between two checks of the journals\' sizes').
:- setting(journal_min_kb, positive_integer, 256,
           'A journal is compacted only past this size (KB)').
:- setting(journal_ratio, float, 0.25,
           'A journal past journal_min_kb is compacted once it outweighs \c
            this fraction of its snapshot').

:- dynamic
    attached/2,                     % Directory, CommitLogStream
    restored/1,                     % Records
    pending/1,                      % Record (thread-local below)
    attaching/0.
:- thread_local
    pending/1,
    attaching/0.

%   rdf_persistency announces how many files it restores even when
%   asked to be silent; the server says what it restored itself.

:- multifile user:message_hook/3.

user:message_hook(rdf(restoring(_, _, _)), informational, _) :-
    attaching.

%!  live_records(-Records) is det.
%
%   Multifile hook: the records still needed, written to a compacted
%   commit log.  Each module that writes records defines a clause for
%   its own; the results are appended.

:- multifile
    live_records/1.

		 /*******************************
		 *        ATTACH / DETACH       *
		 *******************************/

%!  oro_persist_attach(+Directory) is det.
%
%   Make the model graphs persistent in Directory (created if needed),
%   first restoring what it holds.  Fails with a permission error if
%   another process has the directory.
%
%   @error permission_error(lock, rdf_db, Directory) if it is in use.

oro_persist_attach(Dir0) :-
    must_be(atom, Dir0),
    (   exists_directory(Dir0)
    ->  true
    ;   make_directory_path(Dir0)
    ),
    absolute_file_name(Dir0, Dir, [file_type(directory), access(write)]),
    oro_persist_detach,
    commit_log_file(Dir, LogFile),
    read_commit_log(LogFile, Committed, Records),
    repair_directory(Dir, Committed),
    setup_call_cleanup(assertz(attaching),
                       rdf_attach_db(Dir, [access(read_write), silent(true)]),
                       retractall(attaching)),
    flag(oro_persist_seq, _, Committed),
    retractall(restored(_)),
    assertz(restored(Records)),
    write_commit_log(LogFile, Records, Committed),
    open(LogFile, append, Log, [encoding(utf8)]),
    assertz(attached(Dir, Log)),
    setting(compact_every, Every),
    flag(oro_persist_changed, _, Every),    % checked at the first change
    rdf_monitor(oro_persist:count_change, [-all, +assert, +retract, +update]),
    debug(oro(persist), 'Attached ~w (last commit ~d)', [Dir, Committed]).

%!  oro_persist_detach is det.
%
%   Stop journaling: close the journals and the commit log.  Nothing
%   happens if no directory is attached.

oro_persist_detach :-
    (   retract(attached(Dir, Log))
    ->  rdf_monitor(oro_persist:count_change, [-all]),
        close(Log),
        rdf_detach_db,
        retractall(restored(_)),
        debug(oro(persist), 'Detached ~w', [Dir])
    ;   true
    ).

%!  oro_persist_directory(-Directory) is semidet.
%
%   The attached database directory, if any.

oro_persist_directory(Dir) :-
    attached(Dir, _).

%!  oro_persist_records(-Records) is det.
%
%   The committed records found in the commit log when the directory
%   was attached (oldest first), or [] if none is.

oro_persist_records(Records) :-
    (   restored(Records0)
    ->  Records = Records0
    ;   Records = []
    ).

%!  oro_persist_exclude(+Graph) is det.
%
%   Never journal Graph (ontology and scratch graphs).  Call before
%   Graph gets its triples.

oro_persist_exclude(Graph) :-
    must_be(atom, Graph),
    (   attached(_, _)
    ->  rdf_persistency(Graph, false)
    ;   true
    ).

		 /*******************************
		 *          CHANGES             *
		 *******************************/

%!  oro_persist_transaction(+Action, :Goal) is semidet.
%
%   Run Goal as one rdf_transaction/2 and, if a directory is attached
%   and Goal succeeds, commit it to the commit log (with the records
%   Goal added by oro_persist_record/1) before returning.  The caller
%   serialises writers (oro_store's `oro_write` mutex).

oro_persist_transaction(Action, Goal) :-
    (   attached(_, Log)
    ->  retractall(pending(_)),
        flag(oro_persist_seq, Last, Last),
        Seq is Last + 1,
        (   rdf_transaction(Goal, log(oro(Seq, Action)))
        ->  commit(Log, Seq)
        ;   retractall(pending(_)),
            fail
        )
    ;   rdf_transaction(Goal, oro(Action))
    ).

%   A transaction that fails or raises leaves pending records behind;
%   they are dropped by the next transaction (see above), never
%   written.

commit(Log, Seq) :-
    forall(retract(pending(Record)),
           format(Log, '~k.~n', [Record])),
    format(Log, 'commit(~d).~n', [Seq]),
    flush_output(Log),
    flag(oro_persist_seq, _, Seq),
    flag(oro_persist_changed, Changed, Changed),
    setting(compact_every, Every),
    (   Changed >= Every
    ->  flag(oro_persist_changed, _, 0),
        compact(false)
    ;   true
    ).

%   count_change(+Event): an rdf_monitor/2 callback counting the triples
%   changed (added, removed, updated) while a directory is attached, so
%   that the journals are checked after as many triples as
%   compact_every says, be they changed one a transaction or a
%   thousand.

:- public count_change/1.

count_change(_) :-
    flag(oro_persist_changed, N, N+1).

%!  oro_persist_record(+Record) is det.
%
%   Attach Record (a ground term) to the change in progress: it is
%   written to the commit log with the change's commit, and returned by
%   oro_persist_records/1 after a restart.  Nothing happens when no
%   directory is attached.

oro_persist_record(Record) :-
    (   attached(_, _)
    ->  assertz(pending(Record))
    ;   true
    ).

%!  oro_persist_note(+Record) is det.
%
%   Write Record (a ground term) to the commit log at once, flushed:
%   it is committed with the next change that commits, before any of
%   that change's triples can be recovered, and returned by
%   oro_persist_records/1 after a restart.  For what must be on disk
%   before any change depends on it, whether a change is in progress or
%   not (a model's graph names, see oro_store).  A note followed by no
%   commit is dropped on restart, as is what would have depended on
%   it.  Nothing happens when no directory is attached.

oro_persist_note(Record) :-
    (   attached(_, Log)
    ->  format(Log, '~k.~n', [Record]),
        flush_output(Log)
    ;   true
    ).

		 /*******************************
		 *          COMPACTION          *
		 *******************************/

%!  oro_persist_compact is det.
%
%   Compact every journal now, and rewrite the commit log with the live
%   records.  Must be called under the store's write lock.

oro_persist_compact :-
    (   attached(_, _)
    ->  compact(true)
    ;   true
    ).

compact(All) :-
    setting(journal_min_kb, MinKB),
    findall(Graph, compactable(All, MinKB, Graph), Graphs),
    (   Graphs == []
    ->  true
    ;   rdf_gc,                 % snapshots would keep deleted triples
        forall(member(Graph, Graphs),
               ( debug(oro(persist), 'Compacting the journal of ~w', [Graph]),
                 rdf_flush_journals([graph(Graph)])
               ))
    ),
    compact_commit_log(All, MinKB).

%   compactable(+All, +MinKB, -Graph): the journal of Graph is to be
%   compacted: All is `true`, or it is past MinKB and journal_ratio
%   times its snapshot.  The snapshot holds at most the triples live
%   when it was written, and the journal every change since, each
%   record weighing more than a triple of a snapshot: so once the
%   journal outweighs a fraction r of the snapshot, the live triples
%   may have changed by about r of the snapshot's, and the new snapshot
%   replaces both.  Snapshot and journal stay within a constant of the
%   live triples (one that shrank compacts as soon as its removals
%   outweigh r of it).

compactable(All, MinKB, Graph) :-
    rdf_graph(Graph),
    rdf_journal_file(Graph, Journal),
    (   All == true
    ->  true
    ;   size_file(Journal, Size),
        Size > MinKB * 1024,
        (   rdf_snapshot_file(Graph, Snapshot)
        ->  size_file(Snapshot, SnapSize)
        ;   SnapSize = 0
        ),
        setting(journal_ratio, Ratio),
        Size > Ratio * SnapSize
    ).

compact_commit_log(All, MinKB) :-
    attached(Dir, Log),
    commit_log_file(Dir, File),
    size_file(File, LogSize),
    (   ( All == true ; LogSize > MinKB * 1024 )
    ->  findall(R, ( live_records(Rs), member(R, Rs) ), Records),
        flag(oro_persist_seq, Seq, Seq),
        close(Log),
        write_commit_log(File, Records, Seq),
        open(File, append, Log1, [encoding(utf8)]),
        retractall(attached(Dir, _)),
        assertz(attached(Dir, Log1))
    ;   true
    ).

%!  oro_persist_sizes(-Sizes) is det.
%
%   Sizes is a dict with the bytes on disk of the attached directory:
%   `journals`, `snapshots`, `commit_log` and `total`.

oro_persist_sizes(Sizes) :-
    attached(Dir, Log),
    flush_output(Log),
    findall(Ext-Size,
            ( directory_member(Dir, File, [recursive(true)]),
              exists_file(File),
              file_name_extension(_, Ext, File),
              size_file(File, Size)
            ),
            Pairs),
    sum_ext(Pairs, jrn, Journals),
    sum_ext(Pairs, trp, Snapshots),
    sum_ext(Pairs, jnl, CommitLog),
    aggregate_all(sum(S), member(_-S, Pairs), Total),
    Sizes = _{journals:Journals, snapshots:Snapshots,
              commit_log:CommitLog, total:Total}.

sum_ext(Pairs, Ext, Sum) :-
    aggregate_all(sum(S), member(Ext-S, Pairs), Sum).

		 /*******************************
		 *          COMMIT LOG          *
		 *******************************/

commit_log_file(Dir, File) :-
    directory_file_path(Dir, 'oro.jnl', File).

%   read_commit_log(+File, -Committed, -Records)
%
%   Committed is the last sequence number committed (0 if none) and
%   Records the records written with committed changes.  Reading stops
%   at the first term that cannot be read (a line cut by a crash).

read_commit_log(File, Committed, Records) :-
    (   exists_file(File)
    ->  setup_call_cleanup(
            open(File, read, In, [encoding(utf8)]),
            read_log(In, 0, [], [], Committed, Records0),
            close(In)),
        Records = Records0
    ;   Committed = 0,
        Records = []
    ).

read_log(In, Seq0, Pending, Acc, Seq, Records) :-
    catch(read_term(In, Term, []), error(syntax_error(_), _), Term = '$cut'),
    (   ( Term == end_of_file ; Term == '$cut' )
    ->  Seq = Seq0,
        reverse(Acc, Records)
    ;   Term = commit(Seq1)
    ->  append(Pending, Acc, Acc1),
        read_log(In, Seq1, [], Acc1, Seq, Records)
    ;   read_log(In, Seq0, [Term|Pending], Acc, Seq, Records)
    ).

%   write_commit_log(+File, +Records, +Seq): replace File by Records and
%   commit(Seq), atomically (a new file renamed over the old one).

write_commit_log(File, Records, Seq) :-
    atom_concat(File, '.new', New),
    setup_call_cleanup(
        open(New, write, Out, [encoding(utf8)]),
        ( forall(member(R, Records), format(Out, '~k.~n', [R])),
          format(Out, 'commit(~d).~n', [Seq])
        ),
        close(Out)),
    rename_file(New, File).

		 /*******************************
		 *            REPAIR            *
		 *******************************/

%   repair_directory(+Dir, +Committed)
%
%   Before rdf_persistency reads Dir: finish or undo an interrupted
%   compaction, and cut each journal before its first change later than
%   Committed or left incomplete.

repair_directory(Dir, Committed) :-
    forall(directory_member(Dir, New, [recursive(true), extensions([new])]),
           repair_new(Dir, New)),
    forall(directory_member(Dir, Journal, [recursive(true), extensions([jrn])]),
           repair_journal(Journal, Committed)).

%   repair_new(+Dir, +New): a file left by a write interrupted before
%   its rename.
%
%   rdf_persistency compacts by writing Graph.trp.new, deleting the
%   journal, then renaming.  If the journal is gone the new snapshot is
%   complete; otherwise it may not be, and the journal still holds all.
%   The journal is not next to the snapshot: rdf_persistency puts each
%   file in a directory of its own hash, so it is looked for by name
%   in the whole database directory.
%
%   Any other .new file is our commit log being rewritten: the old one
%   is whole (it is replaced only once the new one is written), so the
%   new one is dropped.

repair_new(Dir, New) :-
    file_name_extension(Snapshot, new, New),
    file_name_extension(Base, trp, Snapshot),
    !,
    file_base_name(Base, Name),
    file_name_extension(Name, jrn, JournalName),
    (   directory_member(Dir, Journal, [recursive(true), extensions([jrn])]),
        file_base_name(Journal, JournalName)
    ->  delete_file(New)
    ;   rename_file(New, Snapshot)
    ),
    debug(oro(persist), 'Repaired an interrupted compaction: ~w', [Snapshot]).
repair_new(_, New) :-
    delete_file(New),
    debug(oro(persist), 'Dropped an interrupted rewrite: ~w', [New]).

repair_journal(File, Committed) :-
    setup_call_cleanup(
        open(File, read, In, [encoding(utf8)]),
        journal_cut(In, Committed, none, Cut),
        close(In)),
    (   Cut == none
    ->  true
    ;   truncate_file(File, Cut),
        debug(oro(persist), 'Cut ~w at byte ~d', [File, Cut])
    ).

%   journal_cut(+In, +Committed, +Open, -Cut): Cut is the byte offset
%   where the journal must end, or `none`.  Open is the offset of the
%   begin of the transaction being read, or `none`.

journal_cut(In, Committed, Open, Cut) :-
    byte_offset(In, Here),
    catch(read_term(In, Term, []), error(syntax_error(_), _), Term = '$cut'),
    (   Term == end_of_file
    ->  Cut = Open
    ;   Term == '$cut'
    ->  (   Open == none
        ->  Cut = Here
        ;   Cut = Open
        )
    ;   Term = begin(_, 0, _, Message)
    ->  (   Message = oro(Seq, _),
            Seq > Committed
        ->  Cut = Here
        ;   journal_cut(In, Committed, Here, Cut)
        )
    ;   Term = end(_, 0, _)
    ->  journal_cut(In, Committed, none, Cut)
    ;   journal_cut(In, Committed, Open, Cut)
    ).

byte_offset(In, Offset) :-
    stream_property(In, position(Pos)),
    stream_position_data(byte_count, Pos, Offset).

%   The offset of a term is where reading it started: just after the
%   full stop of the previous one, before its newline.  A newline is put
%   back so that appended lines stay separate terms.

truncate_file(File, Size) :-
    setup_call_cleanup(
        open(File, update, Out, [type(binary)]),
        ( seek(Out, Size, bof, _),
          set_end_of_stream(Out),
          (   Size > 0
          ->  put_byte(Out, 0'\n)
          ;   true
          )
        ),
        close(Out)).
